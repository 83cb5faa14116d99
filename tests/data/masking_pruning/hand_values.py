#!/usr/bin/env python3
"""Expected numbers of tests/synthesis/test_masking_pruning.cpp and tests/cli/test_prune_cli.cpp.

An independent, literal O(N^2) transcription of the rule in synthesis/masking_pruning.hpp (van den Doel,
Pai et al. 2002) using only Python's math module. Run: python3 hand_values.py
Prints, per case, the powers P, levels L, Bark z, masking thresholds T, thresholds in quiet Q and dB
above the threshold A = L - max(T, Q), to 12 decimals.
"""
import math


def bark(f):  # Zwicker-Terhardt
    return 13 * math.atan(0.00076 * f) + 3.5 * math.atan((f / 7500) ** 2)


def quiet(f):  # Terhardt's threshold in quiet, dB SPL
    k = f / 1000
    return 3.64 * k ** -0.8 - 6.5 * math.exp(-0.6 * (k - 3.3) ** 2) + 1e-3 * k ** 4


def analyse(modes, a_v=16.0, playback=70.0, combine="max"):
    P = [a * a / d for f, d, a in modes]
    total = sum(P)
    L = [playback + 10 * math.log10(p / total) if p > 0 else -math.inf for p in P]
    Z = [bark(f) for f, d, a in modes]
    T = []
    for m in range(len(modes)):
        maskings = []
        for n in range(len(modes)):
            if n == m or P[n] == 0:
                continue
            if Z[m] <= Z[n]:
                maskings.append(L[n] - a_v - 25 * (Z[n] - Z[m]))
            else:
                maskings.append(L[n] - a_v - max(0.0, 22 - L[n] / 5) * (Z[m] - Z[n]))
        if not maskings:
            T.append(-math.inf)
        elif combine == "max":
            T.append(max(maskings))
        else:
            T.append(10 * math.log10(sum(10 ** (v / 10) for v in maskings)))
    Q = [quiet(f) for f, d, a in modes]
    A = [L[i] - max(T[i], Q[i]) for i in range(len(modes))]
    return dict(P=P, L=L, z=Z, T=T, Q=Q, A=A)


CASES = [  # name, [(freq_hz, decay_per_s, amp)], options
    ("A: two modes, upper side", [(1000, 1, 1), (1200, 1, 0.1)], {}),
    ("A with a_v = 10", [(1000, 1, 1), (1200, 1, 0.1)], dict(a_v=10)),
    ("A with a_v = 10, 80 dB, sum", [(1000, 1, 1), (1200, 1, 0.1)], dict(a_v=10, playback=80, combine="sum")),
    ("B: same-Bark maskers, max", [(2000, 1, 1), (2000, 1, 1), (1500, 1, 0.1)], {}),
    ("B: same-Bark maskers, sum", [(2000, 1, 1), (2000, 1, 1), (1500, 1, 0.1)], dict(combine="sum")),
    ("C: threshold in quiet", [(1000, 1, 1), (50, 1, 0.01)], {}),
    ("single mode at 0 dB", [(1000, 3, 0.5)], dict(playback=0)),
    ("orderings", [(1100, 10, 1), (1000, 1, 0.5), (60, 0.5, 0.4)], {}),
]

if __name__ == "__main__":
    print("bark(1000) =", f"{bark(1000):.12f}", " bark(16000) =", f"{bark(16000):.12f}")
    print("wsg(1000) =", f"{6 * math.asinh(1000 / 600):.12f}")
    print("quiet(1000) =", f"{quiet(1000):.12f}", " quiet(50) =", f"{quiet(50):.12f}")
    for name, modes, options in CASES:
        print(f"\n{name} {options}")
        for key, values in analyse(modes, **options).items():
            print(f"  {key:2s}", "  ".join(f"{v:.12f}" for v in values))
