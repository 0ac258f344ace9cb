#!/usr/bin/env bash
# Installs, with apt-get, every Debian package rasterlab builds with that is
# not installed yet. Safe to run again: it does nothing when all are there.
# `scripts/setup.sh fuzz` adds clang 14 and libFuzzer for scripts/fuzz.sh;
# `scripts/setup.sh site` adds MkDocs, KaTeX and Chromium for the docs site.
set -euo pipefail

packages=(
  cmake ninja-build g++ pkg-config python3  # build tools
  python3-matplotlib                        # the labs' charts
  libtinyobjloader-dev                      # OBJ loading
  libstb-dev                                # PNG/BMP in, PNG out, Perlin noise
  libturbojpeg0-dev                         # JPEG in (libjpeg-turbo)
  libcli11-dev                              # command lines
  libgtest-dev                              # unit tests
  libbenchmark-dev                          # the labs' timing
  libhwy-dev                                # lesson 12's SIMD (Google Highway)
  libtbb-dev                                # lesson 12's threads (oneTBB)
  libosmesa6-dev                            # lesson 12's peer: Mesa's llvmpipe, off screen
  libembree-dev                             # lesson 10's ray-traced truth (Embree)
  libsdl2-dev xvfb                          # lesson 13's viewer, and its window tests
  python3-dev pybind11-dev                  # the Python module (python/)
  python3-numpy python3-pytest              # its arrays and its tests
  python3-nbclient python3-ipykernel        # its notebook, executed by the tests
  jupyter-nbconvert jupyter-core            # the README's notebook command (jupyter nbconvert)
  python3-venv python3-setuptools python3-pip python3-wheel  # pip install . into a venv
  python3-clang-14                          # checks the headers' examples against their declarations
)

if [ "${1:-}" = "fuzz" ]; then
  packages+=(clang-14 libfuzzer-14-dev libclang-rt-14-dev)  # the fuzz targets
fi
if [ "${1:-}" = "site" ]; then
  packages+=(mkdocs mkdocs-material python3-pymdownx libjs-katex  # the docs site, offline
             chromium)                                           # its browser test
fi

missing=()
for package in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$package")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages are installed"
  exit 0
fi

sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi
echo "setup: installing ${missing[*]}"
"${sudo_cmd[@]}" apt-get update -qq
DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends \
  "${missing[@]}"
echo "setup: done"
