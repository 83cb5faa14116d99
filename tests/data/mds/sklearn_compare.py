#!/usr/bin/python3
# Golden values for the MDS comparison with scikit-learn (tests/analysis/stats/test_mds.cpp,
# MdsVsSklearn.*; tests/bench/mds_vs_sklearn.sh): a seeded 100 x 100 dissimilarity matrix and the
# Kruskal stress-1 of scikit-learn's metric SMACOF (best of its n_init starts) on it.
#
# Matrix: 100 points in 3-D (normal, axis scales 3, 2, 0.8: a noisy "2-D map" with a thin third
# dimension), Euclidean distances plus symmetric |N(0, 0.3^2)| noise, zero diagonal.
# Stress-1 uses the formula of analysis/stats/mds.hpp (ratio-scaled disparities b*delta, b = sum delta d /
# sum delta^2): S1 = sqrt(sum_{i<j} (d_ij - b delta_ij)^2 / sum_{i<j} d_ij^2).
#
# Run from this folder with Debian's Python (numpy, scipy, scikit-learn):
#   /usr/bin/python3 sklearn_compare.py            # writes sklearn_matrix.csv, sklearn_golden.json
#   /usr/bin/python3 sklearn_compare.py --time M.csv [--repeats R]   # only times sklearn's fit on M.csv
import json
import sys
import time

import numpy as np
import sklearn
from scipy.spatial.distance import pdist, squareform
from sklearn.manifold import MDS

SEED = 2002
N = 100


def make_matrix():
    rng = np.random.default_rng(SEED)
    x = rng.standard_normal((N, 3)) * np.array([3.0, 2.0, 0.8])
    d = squareform(pdist(x))
    noise = np.abs(rng.normal(0.0, 0.3, (N, N)))
    d = d + (noise + noise.T) / 2
    np.fill_diagonal(d, 0.0)
    return d


def stress1(delta, points):
    d = squareform(pdist(points))
    iu = np.triu_indices_from(delta, 1)
    dv, dl = d[iu], delta[iu]
    b = (dl * dv).sum() / (dl * dl).sum()
    return float(np.sqrt(((dv - b * dl) ** 2).sum() / (dv ** 2).sum()))


def raw_stress(delta, points):
    d = squareform(pdist(points))
    iu = np.triu_indices_from(delta, 1)
    return float(((d[iu] - delta[iu]) ** 2).sum())


def sklearn_mds():
    # scikit-learn 1.2 defaults spelled out: metric SMACOF, 4 random starts, 300 iterations, eps 1e-3.
    return MDS(n_components=2, metric=True, n_init=4, max_iter=300, eps=1e-3,
               dissimilarity="precomputed", random_state=SEED, n_jobs=None)


def read_matrix(path):
    with open(path) as f:
        rows = [line.strip().split(",") for line in f if line.strip()]
    return np.array([[float(v) for v in r[1:]] for r in rows[1:]])


def main():
    if len(sys.argv) >= 3 and sys.argv[1] == "--time":
        delta = read_matrix(sys.argv[2])
        repeats = int(sys.argv[4]) if len(sys.argv) >= 5 and sys.argv[3] == "--repeats" else 5
        sklearn_mds().fit(delta)  # warm-up (imports, caches)
        times = []
        for _ in range(repeats):
            t0 = time.perf_counter()
            m = sklearn_mds().fit(delta)
            times.append(time.perf_counter() - t0)
        print(json.dumps({"sklearn_fit_seconds_median": float(np.median(times)),
                          "sklearn_fit_seconds_min": float(min(times)), "repeats": repeats,
                          "stress1": stress1(delta, m.embedding_), "n_iter": int(m.n_iter_)}))
        return
    delta = make_matrix()
    labels = ["s%03d" % (i + 1) for i in range(N)]
    with open("sklearn_matrix.csv", "w") as f:
        f.write("stimulus," + ",".join(labels) + "\n")
        for i in range(N):
            f.write(labels[i] + "," + ",".join("%.17g" % v for v in delta[i]) + "\n")
    delta = read_matrix("sklearn_matrix.csv")  # exactly what the C++ test reads
    m = sklearn_mds().fit(delta)
    golden = {
        "n": N, "seed": SEED, "sklearn_version": sklearn.__version__,
        "n_init": 4, "max_iter": 300, "eps": 1e-3, "random_state": SEED,
        "stress1": stress1(delta, m.embedding_),
        "raw_stress": raw_stress(delta, m.embedding_),
        "sklearn_stress_": float(m.stress_),
        "n_iter": int(m.n_iter_),
    }
    with open("sklearn_golden.json", "w") as f:
        json.dump(golden, f, indent=2)
        f.write("\n")
    print(json.dumps(golden))


if __name__ == "__main__":
    main()
