# Sourced by scripts/test.sh: a throw-away PostgreSQL 15 server for the results store's tests.
#   start_test_postgres   initdb in a temp folder (as an unprivileged user), pg_ctl start on a free
#                         loopback port, createdb; exports MODALSTUDY_TEST_POSTGRES_URL. Prints why
#                         and exports nothing when the server binaries are missing.
#   stop_test_postgres    stops the server and removes its folder (safe to call twice; test.sh traps it).
# A server left by a run that was killed is found by its folder's name and stopped first.

pg_bin_dir() {
  local d
  for d in /usr/lib/postgresql/15/bin /usr/lib/postgresql/*/bin; do
    [[ -x "$d/initdb" && -x "$d/pg_ctl" && -x "$d/postgres" ]] && { echo "$d"; return 0; }
  done
  return 1
}

# The unprivileged account that owns the data folder: root may not run postgres.
pg_run_as() {
  if [[ "$(id -u)" -eq 0 ]]; then runuser -u postgres -- "$@"; else "$@"; fi
}

# Servers left by killed runs: their folders are /tmp/modalstudy-pg.* with a postmaster.pid.
stop_abandoned_test_postgres() {
  local bin="$1" dir
  for dir in /tmp/modalstudy-pg.*; do
    [[ -d "$dir" ]] || continue
    if [[ -f "$dir/owner.pid" ]] && kill -0 "$(cat "$dir/owner.pid")" 2>/dev/null; then
      continue  # a live run's
    fi
    # The server may be gone already while its postmaster.pid stays: pg_ctl then fails, harmlessly
    # (under test.sh's `set -e` a bare failing stop would end the whole run without a word).
    if [[ -f "$dir/data/postmaster.pid" ]]; then
      pg_run_as "$bin/pg_ctl" -D "$dir/data" -m immediate stop >/dev/null 2>&1 || true
    fi
    echo "== removed a test PostgreSQL folder left by a killed run: $dir"
    rm -rf "$dir"
  done
}

start_test_postgres() {
  local bin
  if ! bin="$(pg_bin_dir)"; then
    echo "== PostgreSQL tests skipped: no PostgreSQL server binaries (apt-get install postgresql-15)"
    return 0
  fi
  if [[ "$(id -u)" -eq 0 ]] && ! id postgres >/dev/null 2>&1; then
    useradd --system --no-create-home --shell /usr/sbin/nologin postgres
  fi
  stop_abandoned_test_postgres "$bin"
  TEST_PG_DIR="$(mktemp -d /tmp/modalstudy-pg.XXXXXX)"
  echo $$ >"$TEST_PG_DIR/owner.pid"
  [[ "$(id -u)" -eq 0 ]] && chown postgres: "$TEST_PG_DIR"
  # A free loopback port: the kernel picks one, the server takes it a moment later.
  TEST_PG_PORT="$(python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1",0)); print(s.getsockname()[1])')"
  TEST_PG_BIN="$bin"
  pg_run_as "$bin/initdb" -D "$TEST_PG_DIR/data" -U modalstudy --auth=trust -E UTF8 --no-locale >"$TEST_PG_DIR/initdb.log" 2>&1 ||
    { cat "$TEST_PG_DIR/initdb.log"; return 1; }
  # fsync stays on: the tests check that a committed answer survives a killed connection.
  pg_run_as "$bin/pg_ctl" -D "$TEST_PG_DIR/data" -l "$TEST_PG_DIR/server.log" -w -t 30 \
    -o "-c listen_addresses=127.0.0.1 -c port=$TEST_PG_PORT -c unix_socket_directories=$TEST_PG_DIR -c max_connections=300" \
    start >/dev/null || { cat "$TEST_PG_DIR/server.log"; return 1; }
  "$bin/pg_isready" -h 127.0.0.1 -p "$TEST_PG_PORT" -t 30 >/dev/null
  "$bin/createdb" -h 127.0.0.1 -p "$TEST_PG_PORT" -U modalstudy modalstudy_test
  export MODALSTUDY_TEST_POSTGRES_URL="postgresql://modalstudy@127.0.0.1:$TEST_PG_PORT/modalstudy_test"
  echo "== PostgreSQL $("$bin/postgres" --version | awk '{print $3}') for the tests at $MODALSTUDY_TEST_POSTGRES_URL"
}

stop_test_postgres() {
  [[ -n "${TEST_PG_DIR:-}" && -d "$TEST_PG_DIR" ]] || return 0
  pg_run_as "$TEST_PG_BIN/pg_ctl" -D "$TEST_PG_DIR/data" -m fast -w stop >/dev/null 2>&1 || true
  rm -rf "$TEST_PG_DIR"
  TEST_PG_DIR=""
}
