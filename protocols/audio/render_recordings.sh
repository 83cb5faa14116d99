#!/bin/sh
# Renders the stand-in "recordings" of protocols/ab_synthesis_methods.yaml (see its header): each
# Skandalou & Ireland object of stimuli/replications/skandalou2017/ struck at two areas, with what a
# real recording adds and our 10-mode methods lack - a wooden drumstick's finite contact (0.8 ms on
# the bowl and the board, 0.5 ms on the harder objects) where the methods use a unit impulse, every
# mode (up to 2000), close doublets, one-sided random support damping (held by hand) and 50 dB SNR
# room noise. Deterministic: re-running it gives the same files. Usage: protocols/audio/render_recordings.sh [path/to/modalstudy]
set -eu
ms=${1:-build/bin/modalstudy}
here=$(dirname "$0")
sets=$here/../../stimuli/replications/skandalou2017
seed=1
for spec in plastic-bowl:middle:0.0008 plastic-bowl:rim:0.0008 wood-cutting-board:end:0.0008 \
            wood-cutting-board:middle:0.0008 ceramic-plate:middle:0.0005 ceramic-plate:rim:0.0005 \
            glass-bottle:neck:0.0005 glass-bottle:body:0.0005 metal-wok:middle:0.0005 metal-wok:rim:0.0005; do
  obj=${spec%%:*} rest=${spec#*:}
  area=${rest%%:*} contact_s=${rest#*:}
  doublets=""   # discs are never perfectly round: split their degenerate pairs
  grep -q 'type: plate' "$sets/$obj.yaml" && doublets="--set effects.doublets.split_rel=0.002"
  # shellcheck disable=SC2086
  "$ms" synth "$sets/$obj.yaml" -o "$here/$obj-$area.wav" --set hit="$area" \
    --set excitation.type=raised_cosine --set excitation.contact_s="$contact_s" \
    --set effects.support_damping.exponential_mean_per_s=5 --set effects.support_damping.seed=$seed \
    --set effects.noise.snr_db=50 --set effects.noise.seed=$seed $doublets
  seed=$((seed + 1))
done
