#!/usr/bin/python3
# Golden values for analysis/magnitude_estimation (tests/analysis/stats/test_magnitude_estimation.cpp,
# tests/cli/test_cli_stats.cpp): a seeded magnitude-estimation study shaped like Experiment 3 of
# van den Doel et al. (2002): 8 listeners x all 78 pairs (identical pairs included) of 12 tokens
# (the recording "real" and 11 syntheses "m1" .. "m11"), rated against the modulus pair (real, m1).
# Each listener has an own unit and an own exponent (ratings = s_l (0.15 + d_ij)^e_l x log-normal
# noise, rounded to 0.01), and rates the pairs in a shuffled order, either token first.
# The reference computation below is written independently of the C++ (numpy): modulus and
# geometric-mean normalisation, geometric means per listener then across listeners, and metric
# SMACOF from the classical (Torgerson) start (Guttman transform, unit weights, stop when the raw
# stress falls by <= 1e-13 relative), with Kruskal's stress-1 at the optimal ratio scale.
# Run from this folder: /usr/bin/python3 make_golden.py  (writes ratings.csv, golden.json)
import json

import numpy as np

rng = np.random.default_rng(2002)
labels = ["real"] + ["m%d" % k for k in range(1, 12)]
n = len(labels)
# Perceptual positions: good syntheses near the recording, 1-3 modes far away, two clusters between.
pos = np.zeros((n, 2))
for k in range(1, n):
    modes = k  # m1 has the fewest modes, m11 the most
    radius = 6.0 / (1 + 0.35 * modes)
    angle = 0.4 * k + rng.normal(0, 0.2)
    pos[k] = radius * np.array([np.cos(angle), np.sin(angle)])
D = np.sqrt(((pos[:, None, :] - pos[None, :, :]) ** 2).sum(-1))

rows = []
for l in range(8):
    unit = rng.uniform(0.6, 1.8)
    exponent = rng.uniform(0.8, 1.2)
    pairs = [(i, j) for i in range(n) for j in range(i, n)]
    order = rng.permutation(len(pairs))
    for p in order:
        i, j = pairs[p]
        if rng.random() < 0.5:
            i, j = j, i
        r = unit * (0.15 + D[i, j]) ** exponent * np.exp(rng.normal(0, 0.15))
        rows.append(("L%d" % (l + 1), labels[i], labels[j], max(round(r, 2), 0.01)))
with open("ratings.csv", "w") as f:
    f.write("listener,first,second,rating\n")
    for r in rows:
        f.write("%s,%s,%s,%.2f\n" % r)

# --- reference computation (reads back the rounded ratings) ---
listeners = sorted({r[0] for r in rows}, key=lambda s: int(s[1:]))
idx = {s: k for k, s in enumerate(labels)}
logs = {}
for who, a, b, v in rows:
    logs.setdefault(who, []).append((min(idx[a], idx[b]), max(idx[a], idx[b]), np.log(v)))
grand = np.mean([x[2] for who in listeners for x in logs[who]])


def aggregate(log_factor):
    M = np.zeros((n, n))
    for i in range(n):
        for j in range(i + 1, n):
            per = [np.mean([x[2] for x in logs[w] if x[0] == i and x[1] == j]) + log_factor[w] for w in listeners]
            M[i, j] = M[j, i] = np.exp(np.mean(per))
    return M


mod_factor = {w: np.log(10) - np.mean([x[2] for x in logs[w] if x[0] == 0 and x[1] == 1]) for w in listeners}
gm_factor = {w: grand - np.mean([x[2] for x in logs[w]]) for w in listeners}
M_mod = aggregate(mod_factor)
M_gm = aggregate(gm_factor)


def dist(X):
    return np.sqrt(((X[:, None, :] - X[None, :, :]) ** 2).sum(-1))


def classical(Dm, k=2):
    J = np.eye(n) - np.ones((n, n)) / n
    B = -0.5 * J @ (Dm ** 2) @ J
    w, V = np.linalg.eigh(B)
    order = np.argsort(w)[::-1][:k]
    return V[:, order] * np.sqrt(np.maximum(w[order], 0))


def smacof(Dm, X):
    iu = np.triu_indices(n, 1)
    stress = lambda Y: ((Dm - dist(Y))[iu] ** 2).sum()
    X = X - X.mean(0)
    s = stress(X)
    for it in range(1, 20001):
        d = dist(X)
        with np.errstate(divide="ignore", invalid="ignore"):
            B = np.where(d > 0, -Dm / d, 0.0)
        np.fill_diagonal(B, 0)
        np.fill_diagonal(B, -B.sum(1))
        X = B @ X / n
        s_new = stress(X)
        done = s - s_new <= 1e-13 * s
        s = s_new
        if done:
            break
    d = dist(X)[iu]
    dl = Dm[iu]
    b = (dl * d).sum() / (dl * dl).sum()
    return X, s, float(np.sqrt(((d - b * dl) ** 2).sum() / (d ** 2).sum()))


X, raw, s1 = smacof(M_mod, classical(M_mod))
golden = {
    "labels": labels,
    "listeners": listeners,
    "modulus": ["real", "m1"],
    "factor_modulus": [float(np.exp(mod_factor[w])) for w in listeners],
    "factor_geometric": [float(np.exp(gm_factor[w])) for w in listeners],
    "grand_geometric_mean": float(np.exp(grand)),
    "dissimilarity_modulus": M_mod.tolist(),
    "dissimilarity_geometric": M_gm.tolist(),
    "smacof_classical_start": {"raw_stress": float(raw), "stress1": s1, "points": X.tolist()},
}
with open("golden.json", "w") as f:
    json.dump(golden, f, indent=1)
    f.write("\n")
print("stress1", s1, "raw", raw)
