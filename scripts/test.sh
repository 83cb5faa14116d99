#!/usr/bin/env bash
# Quick start 2: set up, build with warnings as errors, run every test suite through CTest.
# A throw-away PostgreSQL 15 server (scripts/test_postgres.sh) runs the results store's PostgreSQL
# tests; it is stopped on exit, however the script ends.
set -Eeuo pipefail
# Under `set -e` a failing step ends the run without a word: name it.
trap 'echo "== scripts/test.sh stopped: \"$BASH_COMMAND\" failed (exit $?) at ${BASH_SOURCE[0]}:$LINENO" >&2' ERR
cd "$(dirname "$0")/.."
./scripts/setup.sh -DMODALSTUDY_WERROR=ON
source scripts/test_postgres.sh
trap stop_test_postgres EXIT
trap 'exit 130' INT TERM
start_test_postgres
ctest --test-dir build --output-on-failure -j"$(nproc)"
