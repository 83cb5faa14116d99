#!/bin/sh
# MDS speed against scikit-learn in one run, on the same 100 x 100 matrix
# (tests/data/mds/sklearn_matrix.csv, made by tests/data/mds/sklearn_compare.py):
#   ours:    build/bin/bench_mds (Google Benchmark, metric SMACOF with the CLI's defaults:
#            classical + 3 random starts = 4, as sklearn) and the whole CLI process
#            `modalstudy stats mds MATRIX --dims 2 --method smacof --json` (wall time, median of 5);
#   sklearn: sklearn.manifold.MDS(metric=True, n_init=4, max_iter=300, eps=1e-3).fit (median of 5,
#            after one warm-up fit; Python start-up and imports not counted).
# Prints both times, the stress-1 of each, and the ratio sklearn / ours.
# Usage (from the repository root, after building): tests/bench/mds_vs_sklearn.sh [BUILD_DIR]
set -eu
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
build=${1:-$root/build}
matrix=$root/tests/data/mds/sklearn_matrix.csv
py=/usr/bin/python3

ours_json=$(MDS_MATRIX=$matrix "$build/bin/bench_mds" --benchmark_filter=BM_SmacofDefaultStarts \
  --benchmark_repetitions=5 --benchmark_report_aggregates_only=true --benchmark_format=json 2>/dev/null)
cli_json=$("$build/bin/modalstudy" stats mds "$matrix" --dims 2 --method smacof --json)
cli_times=""
for i in 1 2 3 4 5; do
  t0=$(date +%s%N)
  "$build/bin/modalstudy" stats mds "$matrix" --dims 2 --method smacof --json >/dev/null
  t1=$(date +%s%N)
  cli_times="$cli_times $t0:$t1"
done
sk_json=$(cd "$root/tests/data/mds" && $py -W ignore sklearn_compare.py --time "$matrix" --repeats 5)

$py - "$ours_json" "$cli_json" "$sk_json" "$cli_times" <<'PYEOF'
import json, statistics, sys
ours, cli, sk, cli_times = json.loads(sys.argv[1]), json.loads(sys.argv[2]), json.loads(sys.argv[3]), sys.argv[4]
med = next(b for b in ours["benchmarks"] if b.get("aggregate_name") == "median")
unit = {"ms": 1e-3, "us": 1e-6, "ns": 1e-9, "s": 1.0}[med["time_unit"]]
ours_s = med["real_time"] * unit
# Process start-up, CSV parsing and JSON output are counted against us.
cli_s = statistics.median((int(b) - int(a)) * 1e-9 for a, b in (p.split(":") for p in cli_times.split()))
sk_s = sk["sklearn_fit_seconds_median"]
print("n = 100, dims = 2, metric SMACOF")
print("ours   (library, %d starts):  %8.2f ms   stress-1 %.9f" % (med["starts"], ours_s * 1e3, med["stress1"]))
print("ours   (CLI process, wall):    %8.2f ms   stress-1 %.9f" % (cli_s * 1e3, cli["stress1"]))
print("sklearn 1.2 MDS.fit (4 starts): %8.2f ms   stress-1 %.9f" % (sk_s * 1e3, sk["stress1"]))
print("speed-up: library %.1fx, CLI process %.1fx" % (sk_s / ours_s, sk_s / cli_s))
PYEOF
