#!/usr/bin/env bash
# Builds everything with warnings as errors and runs the whole test suite (GL tests on Mesa llvmpipe via EGL).
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/setup.sh
cmake --preset ci
cmake --build --preset ci
ctest --preset ci
