#!/bin/sh
# Renders the stand-in "recordings" of protocols/ab_synthesis_methods.yaml (see its header): each
# Skandalou & Ireland object of stimuli/replications/skandalou2017/ struck at two areas, with what a
# real recording adds and our 10-mode methods lack - every mode (up to 2000), close doublets,
# one-sided random support damping (held by hand) and 50 dB SNR room noise. Deterministic: re-running
# it gives the same files. Usage: protocols/audio/render_recordings.sh [path/to/modalstudy]
set -eu
ms=${1:-build/bin/modalstudy}
here=$(dirname "$0")
sets=$here/../../stimuli/replications/skandalou2017
seed=1
for spec in plastic-bowl:middle plastic-bowl:rim wood-cutting-board:end wood-cutting-board:middle \
            ceramic-plate:middle ceramic-plate:rim glass-bottle:neck glass-bottle:body \
            metal-wok:middle metal-wok:rim; do
  obj=${spec%%:*} area=${spec#*:}
  doublets=""   # discs are never perfectly round: split their degenerate pairs
  grep -q 'type: plate' "$sets/$obj.yaml" && doublets="--set effects.doublets.split_rel=0.002"
  # shellcheck disable=SC2086
  "$ms" synth "$sets/$obj.yaml" -o "$here/$obj-$area.wav" --set hit="$area" \
    --set effects.support_damping.exponential_mean_per_s=5 --set effects.support_damping.seed=$seed \
    --set effects.noise.snr_db=50 --set effects.noise.seed=$seed $doublets
  seed=$((seed + 1))
done
