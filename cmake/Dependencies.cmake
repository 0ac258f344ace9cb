# Every dependency is a Debian package; scripts/setup.sh installs them. Each
# lookup below fails with the name of the package to install.

function(rasterlab_require found_var what debian_package)
  if(NOT ${found_var})
    message(FATAL_ERROR
      "${what} not found. Install it with: sudo apt-get install ${debian_package} "
      "(or run scripts/setup.sh, which installs everything rasterlab needs).")
  endif()
endfunction()

find_package(tinyobjloader CONFIG QUIET)
rasterlab_require(tinyobjloader_FOUND "tinyobjloader" libtinyobjloader-dev)

find_package(PkgConfig QUIET)
rasterlab_require(PKG_CONFIG_FOUND "pkg-config" pkg-config)
pkg_check_modules(STB QUIET IMPORTED_TARGET stb)
rasterlab_require(STB_FOUND "stb (pkg-config module 'stb')" libstb-dev)
# JPEG through libjpeg-turbo: stb_image's JPEG decoder reads memory it never
# wrote on some damaged files (common/src/image_io.cpp).
pkg_check_modules(TURBOJPEG QUIET IMPORTED_TARGET libturbojpeg)
rasterlab_require(TURBOJPEG_FOUND "libjpeg-turbo (pkg-config module 'libturbojpeg')" libturbojpeg0-dev)

find_package(CLI11 CONFIG QUIET)
rasterlab_require(CLI11_FOUND "CLI11" libcli11-dev)

find_package(GTest QUIET)
rasterlab_require(GTest_FOUND "GoogleTest" libgtest-dev)

find_package(benchmark CONFIG QUIET)
rasterlab_require(benchmark_FOUND "Google Benchmark" libbenchmark-dev)

# Debian's own Python, which is where python3-matplotlib installs (a Python of
# pyenv or a virtualenv earlier on PATH would not see it).
if(EXISTS /usr/bin/python3 AND NOT Python3_EXECUTABLE)
  set(Python3_EXECUTABLE /usr/bin/python3)
endif()
find_package(Python3 COMPONENTS Interpreter QUIET)
rasterlab_require(Python3_FOUND "Python 3 (docs snippet check, charts)" python3)
execute_process(COMMAND ${Python3_EXECUTABLE} -c "import matplotlib"
                RESULT_VARIABLE matplotlib_missing OUTPUT_QUIET ERROR_QUIET)
if(matplotlib_missing)
  set(matplotlib_FOUND FALSE)
else()
  set(matplotlib_FOUND TRUE)
endif()
rasterlab_require(matplotlib_FOUND "matplotlib for ${Python3_EXECUTABLE} (draws the lab charts)"
                  python3-matplotlib)

# Lesson 12's SIMD and threads, and its peer (Mesa's llvmpipe through
# OSMesa: optional, the lab and the program say the peer is skipped without it).
find_package(hwy CONFIG QUIET)
rasterlab_require(hwy_FOUND "Google Highway" libhwy-dev)
find_package(TBB CONFIG QUIET)
rasterlab_require(TBB_FOUND "oneTBB" libtbb-dev)
# Lesson 10's lab: Embree casts the many rays of the ray-traced occlusion.
find_package(embree 3 CONFIG QUIET)
rasterlab_require(embree_FOUND "Embree 3" libembree-dev)
pkg_check_modules(OSMESA QUIET IMPORTED_TARGET osmesa)
if(NOT OSMESA_FOUND)
  message(STATUS "OSMesa not found (libosmesa6-dev): lesson 12 is built without its llvmpipe peer")
endif()
