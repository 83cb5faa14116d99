#!/usr/bin/env bash
# Fuzzing as a habit: builds the libFuzzer targets of tests/fuzz/ with clang into build-fuzz/ (never
# build/) and runs each for FUZZ_SECONDS (default 45: with the ~90 s build about 5.5 min of CI on two
# cores) from its seed corpus and the regression inputs.
# A crash, an uncaught exception other than InputError, an input taking more than 10 s (-timeout) or
# more than 2 GiB of memory (-rss_limit_mb, -malloc_limit_mb) fails; the input that did it is kept in
# build-fuzz/artifacts/<target>/ (add it to tests/fuzz/regressions/<target>/ once it is fixed).
# Builds and runs take /tmp/ms-build.lock, like every build of the project.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${FUZZ_SECONDS:-45}
targets=(${FUZZ_TARGETS:-paramset protocol csv wav webmushra})
lock=/tmp/ms-build.lock

if ! command -v clang++ >/dev/null; then
  echo "fuzz.sh: clang++ not found (./scripts/setup.sh installs clang and libclang-rt-dev)" >&2
  exit 1
fi
flock "$lock" cmake -S tests/fuzz -B build-fuzz -G Ninja -DCMAKE_CXX_COMPILER=clang++ >/dev/null
flock "$lock" cmake --build build-fuzz

status=0
for t in "${targets[@]}"; do
  found=build-fuzz/corpus/$t     # inputs this machine's runs found; the committed corpus stays small
  artifacts=build-fuzz/artifacts/$t
  mkdir -p "$found" "$artifacts" "tests/fuzz/regressions/$t"
  echo "== fuzz_$t: ${seconds} s"
  if ! flock "$lock" build-fuzz/fuzz_"$t" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
      -malloc_limit_mb=2048 -max_len=65536 -print_final_stats=1 -artifact_prefix="$artifacts/" \
      "$found" "tests/fuzz/corpus/$t" "tests/fuzz/regressions/$t" >"build-fuzz/fuzz_$t.log" 2>&1; then
    echo "fuzz_$t FAILED (input kept in $artifacts/):" >&2
    # The finding, what was thrown (an escaped exception ends in "deadly signal") and our frames.
    grep -E "ERROR|SUMMARY|Test unit written|==[0-9]+==|terminate called|what\(\):| in ms::" \
      "build-fuzz/fuzz_$t.log" | head -30 >&2
    for unit in "$artifacts"/*; do
      [ -f "$unit" ] && { echo "-- $unit (base64):" >&2; head -c 4096 "$unit" | base64 -w 100 >&2; }
    done
    status=1
  else
    grep -E "^stat::number_of_executed_units|^stat::peak_rss_mb" "build-fuzz/fuzz_$t.log" | tr '\n' ' '
    echo
  fi
done
exit $status
