#!/usr/bin/env bash
# Material estimation on real recordings (Debian's hydrogen-drumkits) with a measured object: each
# recording's own modes (modalstudy extract --object-out) stand in for the geometry no one modelled.
# Per recording: Pi_psycho and Pi_hybrid (modalstudy compare) of the object rendered with Ren's metal
# damping at the estimate's level and contact ("before") and with the estimated material ("after").
# Usage: tests/data/estimate_real/run.sh [OUT_DIR]   (from the repository, after the build)
set -euo pipefail
M=${MODALSTUDY:-build/bin/modalstudy}
OUT=${1:-/tmp/estimate_real}
H=/usr/share/hydrogen/data/drumkits
mkdir -p "$OUT"
score() { "$M" compare "$1" "$2" --json | python3 -c "import json,sys;d=json.load(sys.stdin);h=d['hybrid'];print('%.1f %s'%(d['image']['psycho'],'-' if h is None else '%.0f'%h))"; }
one() {
  local n=$1 r=$2 d=$OUT/$1
  mkdir -p "$d"
  "$M" extract "$r" --object-out "$d/object.yaml" >/dev/null
  "$M" estimate "$r" --object "$d/object.yaml" --json -o "$d/material.yaml" --report "$d/report" >"$d/estimate.json"
  read -r sigma contact <<<"$(python3 -c "import json;d=json.load(open('$d/estimate.json'));print(d['material']['sigma'],d['contact_s'])")"
  "$M" synth "$d/object.yaml" --set level.normalize=none --set amp_scale="$sigma" --set excitation.contact_s="$contact" -o "$d/before.wav" >/dev/null
  grep -v '^specific_modulus_m2_s2:' "$d/object.yaml" | sed 's|^material: .*|material: {file: material.yaml}|' >"$d/after.yaml"
  "$M" synth "$d/after.yaml" --set level.normalize=none --set excitation.contact_s="$contact" -o "$d/after.wav" >/dev/null
  python3 -c "import json;d=json.load(open('$d/estimate.json'));m=d['material'];print('| $n | $(score "$r" "$d/before.wav") | $(score "$r" "$d/after.wav") | %.3g | %.3g | %.3g | %.2f | %d | %.1f |'%(m['alpha'],m['beta'],m['gamma'],d['contact_s']*1e3,d['matched_modes'],d['seconds']))"
}
echo "| recording | before: Pi_psycho Pi_hybrid | after: Pi_psycho Pi_hybrid | alpha | beta | gamma (object's 4.59e5) | contact ms | matched | s |"
one "Sangban1 Bell Hit" "$H/circAfrique v4/Sangban1 Bell Hit.wav"
one "AgogoHigh-3" "$H/ForzeeStereo/AgogoHigh-3.wav"
one "AgogoLow-3" "$H/ForzeeStereo/AgogoLow-3.wav"
one "Cowbell-Med" "$H/The Black Pearl 1.0/Cowbell-Med.wav"
one "Clave-Soft" "$H/Gimme A Hand 1.0/Clave-Soft.wav"
one "RideBell-2" "$H/ForzeeStereo/RideBell-2.wav"
one "PaisteBell-Med" "$H/The Black Pearl 1.0/PaisteBell-Med.wav"
