#!/usr/bin/env python3
"""Copies the real recordings the replications play from Debian's hydrogen-drumkits package
(/usr/share/hydrogen/data/drumkits, GPL-2 kits by Glen MacArthur: see README.md here) into this folder,
each scaled to the level of the synthetic clips it is heard among: the RMS of its first 5 ms from the
onset (the first sample at 1 % of the peak) set to -24 dBFS, as `level: {normalize: attack_rms,
target_dbfs: -24}` sets the synthetic ones (their 5 ms from sample 0, the strike). Mono 16-bit PCM in,
mono 16-bit PCM out (the gain is the only change; samples rounded half away from zero). Standard
library only; deterministic. Prints the README's table (source SHA-256, gain, copy SHA-256).

Usage: protocols/audio/hydrogen-drumkits/copy_recordings.py [KITS_DIR]
"""
import array
import hashlib
import math
import os
import sys
import wave

KITS = sys.argv[1] if len(sys.argv) > 1 else "/usr/share/hydrogen/data/drumkits"
HERE = os.path.dirname(os.path.abspath(__file__))
TARGET_DBFS = -24.0
WINDOW_S = 0.005

# (kit, file): what it is. Only genuine strikes: the kits' Clave, WoodBlock and Cowbell "velocity
# layers" are one recording scaled (they agree to -58 dB or better after a gain), so one file each;
# PaisteBell and the two Waterglass instruments are five different strikes each. PaisteRide: the kit's
# "Paiste Ride" struck on its bow, beside "Paiste Bell" on its bell (Skandalou 2017 Exp. 2's two areas).
FILES = [
    ("The Black Pearl 1.0", "PaisteBell-Softest.wav"),
    ("The Black Pearl 1.0", "PaisteBell-Soft.wav"),
    ("The Black Pearl 1.0", "PaisteBell-Med.wav"),
    ("The Black Pearl 1.0", "PaisteBell-Hard.wav"),
    ("The Black Pearl 1.0", "PaisteBell-Hardest.wav"),
    ("The Black Pearl 1.0", "PaisteRide-Med.wav"),
    ("The Black Pearl 1.0", "Cowbell-Med.wav"),
    ("Gimme A Hand 1.0", "Clave-Med.wav"),
    ("Gimme A Hand 1.0", "WoodBlock-Med.wav"),
    ("Gimme A Hand 1.0", "WaterglassHi-Med.wav"),
    ("Gimme A Hand 1.0", "WaterglassLo-Med.wav"),
]


def sha256(path):
    with open(path, "rb") as f:
        return hashlib.sha256(f.read()).hexdigest()


def read_mono16(path):
    with wave.open(path, "rb") as w:
        if w.getnchannels() != 1 or w.getsampwidth() != 2:
            sys.exit(f"{path}: expected mono 16-bit PCM")
        rate = w.getframerate()
        x = array.array("h")
        x.frombytes(w.readframes(w.getnframes()))
    if sys.byteorder != "little":
        x.byteswap()
    return rate, x


def gain_for(x, rate):
    peak = max(abs(v) for v in x)
    onset = next(i for i, v in enumerate(x) if abs(v) >= 0.01 * peak)
    n = int(round(WINDOW_S * rate))
    window = x[onset:onset + n]
    rms = math.sqrt(sum((v / 32768.0) ** 2 for v in window) / len(window))
    return 10.0 ** (TARGET_DBFS / 20.0) / rms, onset


def main():
    print("| copy | source (kit/file) | source SHA-256 | gain dB | copy SHA-256 |")
    print("|---|---|---|---|---|")
    for kit, name in FILES:
        src = os.path.join(KITS, kit, name)
        rate, x = read_mono16(src)
        g, onset = gain_for(x, rate)
        y = array.array("h", (int(math.floor(v * g + 0.5)) for v in x))
        if max(abs(v) for v in y) > 32767:
            sys.exit(f"{src}: the gain would clip")
        if sys.byteorder != "little":
            y.byteswap()
        dst = os.path.join(HERE, name)
        tmp = dst + ".tmp"
        with wave.open(tmp, "wb") as w:
            w.setnchannels(1)
            w.setsampwidth(2)
            w.setframerate(rate)
            w.writeframes(y.tobytes())
        os.replace(tmp, dst)
        print(f"| {name} | {kit}/{name} | {sha256(src)} | {20 * math.log10(g):.4f} | {sha256(dst)} |")


if __name__ == "__main__":
    main()
