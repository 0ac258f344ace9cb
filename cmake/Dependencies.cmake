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

find_package(CLI11 CONFIG QUIET)
rasterlab_require(CLI11_FOUND "CLI11" libcli11-dev)

find_package(GTest QUIET)
rasterlab_require(GTest_FOUND "GoogleTest" libgtest-dev)

find_package(benchmark CONFIG QUIET)
rasterlab_require(benchmark_FOUND "Google Benchmark" libbenchmark-dev)

find_package(Python3 COMPONENTS Interpreter QUIET)
rasterlab_require(Python3_FOUND "Python 3 (runs the docs snippet check)" python3)
