#!/bin/sh
# Pictures of every studyapp view for the README (docs/images/*.png, a 1024x600 screen at 100 %), and
# the same session on a 1366x768 screen at QT_SCALE_FACTOR=1.5 (written to build/gui-tests/readme-1366x768,
# not committed). Both runs fail if an interactive widget is clipped. Needs Xvfb and a built tests_gui:
#   flock /tmp/ms-build.lock cmake --build build --target studyapp tests_gui && scripts/screenshots.sh
set -eu
cd "$(dirname "$0")/.."
build=${BUILD_DIR:-build}
out=${1:-docs/images}
command -v Xvfb >/dev/null || { echo "screenshots.sh: Xvfb is needed (apt-get install xvfb)" >&2; exit 2; }
mkdir -p "$out"

# run SCREEN SCALE OUTDIR DISPLAY
run() {
  Xvfb ":$4" -screen 0 "$1x24" -nolisten tcp >/dev/null 2>&1 &
  xvfb=$!
  trap 'kill $xvfb 2>/dev/null' EXIT
  sleep 1
  status=0
  DISPLAY=":$4" QT_QPA_PLATFORM=xcb QT_SCALE_FACTOR="$2" MODALSTUDY_README_SHOTS="$3" \
    "$build/bin/tests_gui" --gtest_filter='ReadmePictures.*' || status=$?
  kill "$xvfb" 2>/dev/null || true
  trap - EXIT
  return $status
}

run 1024x600 1 "$out" 57
run 1366x768 1.5 "$build/gui-tests/readme-1366x768" 58
ls -l "$out"/*.png
