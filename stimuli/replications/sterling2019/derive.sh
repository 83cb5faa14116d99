#!/usr/bin/env bash
# Derives the synthetic datasets of protocols/sterling2019.yaml from its "recorded" sounds, by the
# project's own estimation path, as the paper derived its EMG dataset from its recordings:
#   emg  Sterling et al.'s estimator: the modes of several strikes extracted (modalstudy extract) and the
#        hybrid and Rayleigh laws fitted by the EMG likelihood (fit-damping --estimator emg) with the
#        paper's constant spread where its Rayleigh fit is a law (every parameter >= 0, converged), else
#        with the relative spread (where neither Rayleigh fit is, the first spread whose hybrid fit is);
#        the emg dataset uses the hybrid fit (the paper's) where it is a law, else the Rayleigh fit -> derived/emg-choice.csv (cell, law, spread)
#   ray  stand-in for the hand-tuned dataset (people matching a Rayleigh law to the sound by ear): the
#        Rayleigh law that minimises Ren et al.'s perceptual distance to the played sound (modalstudy
#        estimate, on the object's geometry; its gamma is reported, the protocol keeps the object's E/rho
#        so only damping differs)
# The ren dataset is Ren et al.'s published parameters (library ren2013/*), as in the paper: not derived.
#
# CELL is shape-material. Where hydrogen-drumkits has the object (protocols/audio/hydrogen-drumkits/):
#   disc-metal  a Paiste ride cymbal's bell, PaisteBell-Med played, its five strikes fitted
#   rod-wood    a clave, Clave-Med, one strike (the kit's other layers are the same strike scaled)
# their geometry is the recording's own modes (extract --object-out -> derived/object-CELL.yaml, E/rho
# of the library material). Elsewhere the sound is a richer-model stand-in (standins/CELL.yaml), and
# ten strikes of it are rendered: the played one as written, nine more struck elsewhere and held
# elsewhere (other contact positions) with other noise and click seeds, as the paper's ~50 strikes per
# object varied hit point and support.
#
# Every fit goes to derived/fits.csv (cell, dataset emg-constant | emg-relative | ray, law, alpha1, alpha2,
# alpha3, the estimate's gamma); protocols/sterling2019.yaml repeats the chosen ones (a test checks):
# when every cell is derived into derived/, set_protocol_laws.py writes them into its emg and ray sets.
# Deterministic: re-running gives the same files (tests/cli/test_sterling2019_derivation.cpp re-derives
# two cells and compares bytes).
# Usage (from the repository, after the build):
#   stimuli/replications/sterling2019/derive.sh [MODALSTUDY [OUT_DIR [CELL...]]]   (default: all cells;
#   some cells only into an OUT_DIR other than derived/)
set -euo pipefail
M=${1:-build/bin/modalstudy}
HERE=stimuli/replications/sterling2019
REC=protocols/audio/hydrogen-drumkits
OUT=${2:-$HERE/derived}
CELLS=("${@:3}")
wanted() { [[ ${#CELLS[@]} -eq 0 || " ${CELLS[*]} " == *" $1 "* ]]; }
mkdir -p "$OUT"
INTO_COMMITTED=; [[ $(realpath "$OUT") == $(realpath "$HERE/derived") ]] && INTO_COMMITTED=1
# fits.csv holds the cells derived in one run: some cells written over the committed files would drop
# the other cells' rows, which the protocol plays.
if [[ ${#CELLS[@]} -gt 0 && -n $INTO_COMMITTED ]]; then
  echo "derive.sh: deriving only ${CELLS[*]} into $HERE/derived would drop the other cells' fits; derive every cell there, or these into another folder" >&2
  exit 2
fi
WORK=$(mktemp -d)   # the strikes and fits (removed at the end)
[[ -n ${KEEP:-} ]] || trap 'rm -rf "$WORK"' EXIT   # KEEP=1 keeps them (the path is printed)
[[ -n ${KEEP:-} ]] && echo "work files: $WORK" >&2

fits_row() {  # cell dataset json-file law
  python3 - "$@" <<'PY'
import json, sys
cell, dataset, path, law = sys.argv[1:5]
d = json.load(open(path))
if "params" in d:  # fit-damping
    p, gamma = d["params"], ""
else:  # estimate
    p, gamma = {"alpha": d["material"]["alpha"], "beta": d["material"]["beta"]}, repr(d["material"]["gamma"])
alpha3 = repr(p["alpha3"]) if "alpha3" in p else ""
print(f"{cell},{dataset},{law},{p['alpha']!r},{p['beta']!r},{alpha3},{gamma}")
PY
}

echo "cell,dataset,law,alpha1,alpha2,alpha3,gamma_estimated" >"$WORK/fits.csv"
echo "cell,law,noise" >"$WORK/emg-choice.csv"

# A fit is a law when every parameter is finite and >= 0 and the optimiser converged (no warning).
is_law() {  # fit.json fit.err
  python3 - "$1" "$2" <<'PY'
import json, math, sys
p = json.load(open(sys.argv[1]))["params"]
ok = all(math.isfinite(v) and v >= 0 for v in p.values()) and "before converging" not in open(sys.argv[2]).read()
sys.exit(0 if ok else 1)
PY
}

derive() {  # cell object.yaml played.wav strike.wav...
  local cell=$1 object=$2 played=$3 noise
  shift 3
  "$M" extract "$@" -o "$WORK/$cell-features.csv" >/dev/null
  # The paper's EMG (constant spread) where its Rayleigh fit is a law; else the relative spread
  # (fit-damping's choice for features measured from sounds, where the constant one can diverge).
  for noise in constant relative; do
    for law in hybrid rayleigh; do
      "$M" fit-damping "$WORK/$cell-features.csv" --law $law --estimator emg --noise $noise --json \
        >"$WORK/$cell-$law-$noise.json" 2>"$WORK/$cell-$law-$noise.err"
      fits_row "$cell" "emg-$noise" "$WORK/$cell-$law-$noise.json" $law >>"$WORK/fits.csv"
    done
  done
  # Where no Rayleigh fit is a law (alpha1 a hair below 0 on the ride bell, whose modes barely lose
  # to viscosity), the first spread whose hybrid fit is one.
  local law=
  for noise in constant relative; do
    is_law "$WORK/$cell-rayleigh-$noise.json" "$WORK/$cell-rayleigh-$noise.err" && { law=rayleigh; break; }
  done
  if [[ -z $law ]]; then
    for noise in constant relative none; do
      [[ $noise == none ]] && { echo "$cell: no EMG fit is a law" >&2; exit 1; }
      is_law "$WORK/$cell-hybrid-$noise.json" "$WORK/$cell-hybrid-$noise.err" && break
    done
  fi
  is_law "$WORK/$cell-hybrid-$noise.json" "$WORK/$cell-hybrid-$noise.err" && law=hybrid
  echo "$cell,$law,$noise" >>"$WORK/emg-choice.csv"
  "$M" estimate "$played" --object "$object" --json >"$WORK/$cell-estimate.json"
  fits_row "$cell" ray "$WORK/$cell-estimate.json" rayleigh >>"$WORK/fits.csv"
  echo "$cell: $(($(wc -l <"$WORK/$cell-features.csv") - 1)) modes from $# strikes; emg: the $law fit, $noise spread" >&2
}

# Real recordings: the object is the played recording's own modes.
if wanted disc-metal; then
  "$M" extract "$REC/PaisteBell-Med.wav" --object-out "$OUT/object-disc-metal.yaml" --material sterling2019/steel >/dev/null
  derive disc-metal "$OUT/object-disc-metal.yaml" "$REC/PaisteBell-Med.wav" \
    "$REC"/PaisteBell-{Softest,Soft,Med,Hard,Hardest}.wav
fi
if wanted rod-wood; then
  "$M" extract "$REC/Clave-Med.wav" --object-out "$OUT/object-rod-wood.yaml" --material sterling2019/wood >/dev/null
  derive rod-wood "$OUT/object-rod-wood.yaml" "$REC/Clave-Med.wav" "$REC/Clave-Med.wav"
fi

# Stand-ins: ten strikes each (the first is the played one, as written).
strikes() {  # cell -> $WORK/cell/strike0..9.wav
  local cell=$1 key hits c1 c2
  if [[ $cell == disc-* ]]; then
    key=object.hit_radius
    hits=(0.3 0.2 0.45 0.6 0.75 0.25 0.5 0.35 0.65 0.8)
    c1=(0.97 0.95 0.9 0.97 0.85 0.93 0.97 0.9 0.95 0.88) c2=(0.12 0.2 0.1 0.3 0.15 0.25 0.05 0.4 0.18 0.1)
  else
    key=object.hit_position
    hits=(0.1 0.05 0.15 0.3 0.4 0.08 0.2 0.35 0.45 0.12)
    c1=(0.22 0.2 0.25 0.18 0.22 0.3 0.15 0.24 0.2 0.26) c2=(0.78 0.8 0.75 0.7 0.85 0.78 0.82 0.65 0.9 0.76)
  fi
  mkdir -p "$WORK/$cell"
  "$M" synth "$HERE/standins/$cell.yaml" -o "$WORK/$cell/strike0.wav" >/dev/null
  for k in 1 2 3 4 5 6 7 8 9; do
    "$M" synth "$HERE/standins/$cell.yaml" -o "$WORK/$cell/strike$k.wav" --set "$key=${hits[$k]}" \
      --set "effects.support_damping.contacts=[{position: ${c1[$k]}, c: 2}, {position: ${c2[$k]}, c: 2}]" \
      --set "effects.noise.seed=$((k + 1))" --set "effects.transient.seed=$((k + 1))" >/dev/null
  done
}
for cell in disc-wood disc-plastic disc-glass disc-porcelain rod-metal rod-plastic rod-glass rod-porcelain; do
  wanted "$cell" || continue
  strikes "$cell"
  object=$HERE/disc.yaml
  [[ $cell == rod-* ]] && object=$HERE/rod.yaml
  derive "$cell" "$object" "$WORK/$cell/strike0.wav" "$WORK/$cell"/strike{0,1,2,3,4,5,6,7,8,9}.wav
done
# Each file replaced whole (a copy beside it, then a rename), so a kill never leaves half a table.
for table in fits.csv emg-choice.csv; do
  cp "$WORK/$table" "$OUT/.$table.part" && mv -f "$OUT/.$table.part" "$OUT/$table"
done
# The protocol plays the committed fits, so it follows them only when all of them were derived again.
if [[ ${#CELLS[@]} -eq 0 && -n $INTO_COMMITTED ]]; then
  python3 "$HERE/set_protocol_laws.py" "$OUT" protocols/sterling2019.yaml >/dev/null
fi
