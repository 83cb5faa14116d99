#!/usr/bin/env bash
# Quick start 1: set up, build, render every shipped parameter set (stimuli/) into build/stimuli/,
# and show where they are. Re-running renders only what changed.
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
echo
echo "Stimuli: $(pwd)/build/stimuli/ (WAV files, manifest.json with SHA-256 and recipe hashes)"
