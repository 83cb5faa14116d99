#!/usr/bin/env bash
# Quick start 1 (the main job): set up and build; render every shipped parameter set into
# build/stimuli/; run the demo study (protocols/demo.yaml) end to end — in the window when there is a
# display, with the simulated listener (autopilot) when there is none — then export the results and
# compute the statistics and pictures from them. Re-running renders only what changed.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/setup.sh -DMODALSTUDY_WERROR=ON  # same configuration as test.sh: one build serves both
echo "== rendering the shipped stimuli (both cores)"
build/bin/modalstudy stimuli build stimuli -o build/stimuli
echo "== one of them, regenerated with an override and its modes written out"
build/bin/modalstudy synth stimuli/plate/sterling-steel.yaml -o build/stimuli/steel-plate-soft.wav \
  --set excitation.contact_s=0.002 --modes-out build/stimuli/steel-plate-modes.csv
echo "== synthesis throughput on one core (4096 modes, 2 s)"
build/bin/modalstudy bench synth --modes 4096 --seconds 2

study=build/demo-study
rm -rf "$study"
mkdir -p "$study"
echo "== the demo study: protocols/demo.yaml (every block type), checked"
build/bin/modalstudy protocol check protocols/demo.yaml
if [[ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" && -z "${MODALSTUDY_AUTOPILOT:-}" ]]; then
  echo "== a display is available: the study opens in a window (participant 'you'; close it to go on)"
  build/bin/studyapp protocols/demo.yaml --participant you --db "$study/results.sqlite" \
    --cache build/stimulus-cache || echo "(window closed before the end: the session resumes next time)"
fi
echo "== four simulated participants answer every trial (headless autopilot)"
for p in P01 P02 P03 P04; do
  build/bin/studyapp protocols/demo.yaml --participant "$p" --db "$study/results.sqlite" \
    --cache build/stimulus-cache --autopilot "${p#P}"
done
echo "== export: tidy CSV, one table per block type"
build/bin/modalstudy export "$study/results.sqlite" -o "$study/export"
echo "== MUSHRA summary (hidden reference 'full', anchors 'full~lp3500' and 'full~lp7000')"
build/bin/modalstudy stats mushra "$study/export/mushra.csv" --reference full \
  --anchor full~lp3500 --anchor full~lp7000 --plot "$study/mushra.png"
echo "== BS.1116: the pruned plate against the full one (difference grades)"
build/bin/modalstudy stats bs1116 "$study/export/bs1116.csv"
echo "== identification: confusion matrix"
build/bin/modalstudy stats confusion "$study/export/identify.csv" --truth stimulus --response response \
  --plot "$study/confusion.png"
echo "== staircase thresholds (a_v, dB), one track per participant"
build/bin/modalstudy stats staircase "$study/export/staircase.csv" --level level --track participant \
  --trial step
echo "== method of limits (a_v, dB): the level before the first change heard, one series per participant"
build/bin/modalstudy stats limits "$study/export/limits.csv" --level level --response response \
  --track participant,block,trial
echo "== adaptive tokens: tokens each participant distinguished, of the sequence's 6 (van den Doel 2002, Table 2)"
build/bin/modalstudy stats tokens "$study/export/tokens.csv"
echo "== change points: sweeps marking a material change at each Q (Skandalou & Ireland 2017, Fig. 5.4)"
build/bin/modalstudy stats changepoint "$study/export/changepoint.csv"
echo
echo "Stimuli: $(pwd)/build/stimuli/ (WAV files, manifest.json with SHA-256 and recipe hashes)"
echo "Study:   $(pwd)/$study/ (results.sqlite, export/*.csv, mushra.png, confusion.png)"
