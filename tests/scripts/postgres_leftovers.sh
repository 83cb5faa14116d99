#!/usr/bin/env bash
# A run of scripts/test.sh killed at a bad moment leaves its PostgreSQL folder behind, with the server
# still running or already gone (its postmaster.pid stays either way). The next run must clear both
# and start its own server, under test.sh's `set -e`, where pg_ctl's failing stop of a gone server
# must not end it.
set -euo pipefail
source_dir="$1"
source "$source_dir/scripts/test_postgres.sh"
bin="$(pg_bin_dir)" || { echo "SKIP: no PostgreSQL server binaries (apt-get install postgresql-15)"; exit 77; }
fail() { echo "FAIL: $*"; exit 1; }

handoff="$(mktemp)"
# A process id that is surely not running: a finished child's.
true & dead_pid=$!; wait "$dead_pid"

# 1. The server still runs, its owner is gone without stopping it (as after SIGKILL: no trap is set here).
bash -c "source '$source_dir/scripts/test_postgres.sh'; start_test_postgres >/dev/null; \
  echo \"\$TEST_PG_DIR \$TEST_PG_PORT\" >'$handoff'"
read -r running running_port <"$handoff"
rm -f "$handoff"
"$bin/pg_isready" -q -h 127.0.0.1 -p "$running_port" -t 10 || fail "the left-over server did not start"

# 2. The server is gone (made after 1: starting that server clears it), its postmaster.pid stays.
gone="$(mktemp -d /tmp/modalstudy-pg.XXXXXX)"
mkdir -p "$gone/data"
echo "$dead_pid" >"$gone/owner.pid"
printf '%s\n%s\n' "$dead_pid" "$gone/data" >"$gone/data/postmaster.pid"

# A live run's folder is left alone.
live="$(mktemp -d /tmp/modalstudy-pg.XXXXXX)"
echo $$ >"$live/owner.pid"

# The next run, under test.sh's own shell options.
out="$(bash -c "set -euo pipefail; source '$source_dir/scripts/test_postgres.sh'; start_test_postgres; \
  \"\$TEST_PG_BIN/pg_isready\" -q -h 127.0.0.1 -p \"\$TEST_PG_PORT\" -t 10; stop_test_postgres; echo ran-its-own" 2>&1)" ||
  fail "the next run ended early: $out"
[[ "$out" == *ran-its-own* ]] || fail "the next run did not start its own server: $out"
[[ ! -e "$gone" ]] || fail "left $gone"
[[ ! -e "$running" ]] || fail "left $running"
! "$bin/pg_isready" -q -h 127.0.0.1 -p "$running_port" -t 2 || fail "the left-over server on port $running_port still runs"
[[ -d "$live" ]] || fail "removed a live run's folder"
rm -rf "$live"
echo "PASS: both left-over folders cleared, the live one kept, a new server started and stopped"
