#!/usr/bin/env bash
# Sets up, builds and runs every test: scripts/test.sh [preset]
# The preset is release (default), debug, asan, fuzz (clang, ASan and UBSan,
# with the libFuzzer targets) or tsan (the tests labelled tsan: lessons 09, 10 and 12, the
# file writers and Python's threads test); see CMakePresets.json.
set -euo pipefail
cd "$(dirname "$0")/.."
preset="${1:-release}"

if [ "$preset" = fuzz ]; then scripts/setup.sh fuzz; else scripts/setup.sh; fi
cmake --preset "$preset"
cmake --build --preset "$preset"
ctest --preset "$preset"
