#!/usr/bin/env bash
# Installs the Debian 12 packages ModalStudy needs (as root, only those missing), then configures and
# builds into build/ (executables in build/bin/). Extra arguments go to the CMake configure step.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(build-essential cmake ninja-build pkg-config
          libsndfile1-dev libeigen3-dev libboost-dev libboost-math-dev libfftw3-dev libyaml-cpp-dev
          libcli11-dev nlohmann-json3-dev libssl-dev libsqlite3-dev
          libpq-dev postgresql-15  # the PostgreSQL back end of the results store; the server for its tests
          libgtest-dev libgmock-dev libbenchmark-dev
          qt6-base-dev qt6-charts-dev qt6-svg-dev qt6-multimedia-dev libgl-dev
          xvfb xauth  # the GUI screenshot test runs under xvfb-run when it is there
          hydrogen-drumkits  # real struck-metal recordings for the model-audit tests (~140 MB)
          libqt6opengl6-dev  # Qt6Charts' CMake config needs Qt6OpenGL; Debian 12 does not pull it in
          clang libclang-rt-dev  # scripts/fuzz.sh: libFuzzer and the sanitizers' runtimes
          chromium nodejs  # the real-browser test of `modalstudy serve` (tests/web)
          python3)  # the test scripts' helpers: a free port for PostgreSQL, the Sterling 2019 derivation
# Debian's npm, unless the installed nodejs brings its own npm (as some nodejs builds do).
command -v npm >/dev/null 2>&1 || packages+=(npm)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "== installing: ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# playwright-core (pinned in tests/web/package-lock.json) drives the system chromium: no browser download.
if [[ ! -f tests/web/node_modules/playwright-core/package.json ||
      tests/web/package-lock.json -nt tests/web/node_modules/.package-lock.json ]]; then
  echo "== npm ci in tests/web (playwright-core)"
  (cd tests/web && PLAYWRIGHT_SKIP_BROWSER_DOWNLOAD=1 npm ci --no-audit --no-fund --loglevel=error)
fi

cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
cmake --build build -j"$(nproc)"
