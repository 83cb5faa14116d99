#!/usr/bin/env bash
# Quick start 2: set up, build with warnings as errors, run every test suite through CTest.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/setup.sh -DMODALSTUDY_WERROR=ON
ctest --test-dir build --output-on-failure -j"$(nproc)"
