#!/usr/bin/env python3
"""Writes the derived damping laws into the protocol's emg-* and ray-* stimuli.

derive.sh fits the laws (DERIVED/fits.csv) and picks the EMG law and spread per cell
(DERIVED/emg-choice.csv); protocols/sterling2019.yaml repeats them digit for digit in each stimulus's
`set: {... damping: {law: ...} ...}` line. This rewrites only those damping maps, so comments, order and
every other key stay as written.

Usage: set_protocol_laws.py DERIVED_DIR PROTOCOL [--check]
  --check  write nothing; list the lines that differ and exit 1 if any do.
Errors are one line (file:line: problem), exit 2, and leave the protocol untouched.
"""
import csv
import os
import re
import sys
import tempfile

STIMULUS = re.compile(r"^  (emg|ray)-([a-z]+-[a-z]+):\s*$")
DAMPING = re.compile(r"damping: \{law:[^}]*\}")


class Bad(Exception):
    pass


def read_rows(path, columns):
    try:
        with open(path, newline="") as f:
            reader = csv.DictReader(f)
            missing = [c for c in columns if c not in (reader.fieldnames or [])]
            if missing:
                raise Bad(f"{path}:1: missing column(s) {', '.join(missing)}")
            return [(reader.line_num, row) for row in reader]
    except OSError as e:
        raise Bad(f"{path}: {e.strerror}")


def damping_map(law, alpha1, alpha2, alpha3):
    # The fits' own repr() digits, so the protocol plays exactly the fitted law.
    text = f"damping: {{law: {law}, alpha1: {alpha1}, alpha2: {alpha2}"
    return text + (f", alpha3: {alpha3}}}" if law == "hybrid" else "}")


def laws(derived):
    choice_csv, fits_csv = os.path.join(derived, "emg-choice.csv"), os.path.join(derived, "fits.csv")
    choice = {}
    for line, r in read_rows(choice_csv, ["cell", "law", "noise"]):
        if r["law"] not in ("hybrid", "rayleigh"):
            raise Bad(f"{choice_csv}:{line}: law '{r['law']}' is neither hybrid nor rayleigh")
        choice[r["cell"]] = (r["law"], "emg-" + r["noise"])
    fits = {}
    for line, r in read_rows(fits_csv, ["cell", "dataset", "law", "alpha1", "alpha2", "alpha3"]):
        for k in ("alpha1", "alpha2") + (("alpha3",) if r["law"] == "hybrid" else ()):
            try:
                float(r[k])
            except ValueError:
                raise Bad(f"{fits_csv}:{line}: {k} '{r[k]}' is not a number")
        fits[(r["cell"], r["dataset"], r["law"])] = (r["alpha1"], r["alpha2"], r["alpha3"])
    out = {}
    for cell, (law, dataset) in choice.items():
        out[("emg", cell)] = (law, fits.get((cell, dataset, law)), f"{fits_csv}: no {dataset} {law} fit for {cell}")
    for cell in {c for c, _, _ in fits}:
        out[("ray", cell)] = ("rayleigh", fits.get((cell, "ray", "rayleigh")), f"{fits_csv}: no ray fit for {cell}")
    return out


def rewrite(text, protocol, table):
    lines = text.split("\n")
    stimulus, seen, changed = None, set(), []
    for i, line in enumerate(lines):
        m = STIMULUS.match(line)
        if m:
            stimulus = (m.group(1), m.group(2))
            continue
        if re.match(r"^ {0,2}\S", line):
            stimulus = None
        if stimulus is None or not line.lstrip().startswith("set:"):
            continue
        if stimulus not in table:
            raise Bad(f"{protocol}:{i + 1}: {stimulus[0]}-{stimulus[1]} has no derived law (cell missing from the fits)")
        law, fit, missing = table[stimulus]
        if fit is None:
            raise Bad(missing)
        if len(DAMPING.findall(line)) != 1:
            raise Bad(f"{protocol}:{i + 1}: expected one 'damping: {{law: ...}}' map in this set: line")
        new = DAMPING.sub(lambda _: damping_map(law, *fit), line)
        seen.add(stimulus)
        if new != line:
            changed.append((i + 1, line.strip(), new.strip()))
            lines[i] = new
        stimulus = None
    unplaced = sorted(set(table) - seen)
    if unplaced:
        raise Bad(f"{protocol}: no set: line for {', '.join(d + '-' + c for d, c in unplaced)}")
    return "\n".join(lines), changed


def main(argv):
    args = [a for a in argv if a != "--check"]
    if len(args) != 2:
        print(next(p for p in __doc__.split("\n\n") if p.startswith("Usage")), file=sys.stderr)
        return 2
    derived, protocol = args
    try:
        try:
            with open(protocol) as f:
                text = f.read()
        except OSError as e:
            raise Bad(f"{protocol}: {e.strerror}")
        new, changed = rewrite(text, protocol, laws(derived))
    except Bad as e:
        print(e, file=sys.stderr)
        return 2
    for line, old, now in changed:
        print(f"{protocol}:{line}: {old}\n  -> {now}")
    if "--check" in argv:
        return 1 if changed else 0
    if changed:  # replace, never leave a half-written protocol
        fd, tmp = tempfile.mkstemp(dir=os.path.dirname(os.path.abspath(protocol)), prefix=".laws-")
        try:
            with os.fdopen(fd, "w") as f:
                f.write(new)
            os.chmod(tmp, os.stat(protocol).st_mode & 0o777)
            os.replace(tmp, protocol)
        except BaseException:
            os.unlink(tmp)
            raise
    print(f"{protocol}: {len(changed)} damping law(s) rewritten", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
