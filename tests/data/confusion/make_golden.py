#!/usr/bin/env python3
"""Golden values for the confusion-matrix statistics (tests/analysis/stats/test_confusion.cpp, tests/cli).

1. Transcribes Tables III and IV of US 9,401,684 (Ren, Yeh, Lin; the 2013 material-identification
   study): recognition-rate matrices in percent for recorded and synthesised sounds, and computes
   the Frobenius norm of their difference (the patent states none).
2. Draws two seeded response files from those tables (listeners identify the material of a sound),
   and computes with scikit-learn and SciPy: confusion_matrix, accuracy_score, recall_score,
   cohen_kappa_score, chi2_contingency, and per-class 95 % Newcombe hybrid score intervals of the
   recall differences (Wilson limits from scipy.stats.binomtest(...).proportion_ci('wilson')).

Run from this folder: python3 make_golden.py   (Debian: python3-sklearn python3-scipy python3-numpy)
"""
import csv
import json

import numpy as np
import scipy
import sklearn
from scipy.stats import binomtest, chi2_contingency
from sklearn.metrics import accuracy_score, cohen_kappa_score, confusion_matrix, recall_score

LABELS = ["wood", "plastic", "metal", "porcelain", "glass"]
# Table III: recorded sounds; rows = recorded material, columns = recognised material, percent.
TABLE_III = [[50.7, 47.9, 0.0, 0.0, 1.4],
             [37.5, 37.5, 6.3, 0.0, 18.8],
             [0.0, 0.0, 66.1, 9.7, 24.2],
             [0.0, 0.0, 1.2, 15.1, 83.7],
             [1.7, 1.7, 1.7, 21.6, 73.3]]
# Table IV: sounds synthesised with the estimated parameters.
TABLE_IV = [[52.8, 43.5, 0.0, 0.0, 3.7],
            [43.0, 52.7, 0.0, 2.2, 2.2],
            [1.8, 1.8, 69.6, 15.2, 11.7],
            [0.0, 1.1, 7.4, 29.8, 61.7],
            [3.3, 3.3, 3.8, 40.4, 49.2]]


def write_table(path, table):
    with open(path, "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(["material"] + LABELS)
        for label, row in zip(LABELS, table):
            w.writerow([label] + [f"{v:.1f}" for v in row])


write_table("ren2013_table3_recorded_percent.csv", TABLE_III)
write_table("ren2013_table4_synthesised_percent.csv", TABLE_IV)
ren = {"frobenius_table3_table4": float(np.linalg.norm(np.array(TABLE_III) - np.array(TABLE_IV)))}

rng = np.random.default_rng(2013)
STIMULI = {"wood": ["plate, 20 cm"], "plastic": ["plate, 20 cm"], "metal": ["plate, 20 cm"],
           "porcelain": ["plate, 20 cm"], "glass": ["bowl \"small\"", "bowl, large"]}


def draw(path, table, listeners, repeats):
    rows = []
    for li in range(listeners):
        for t, label in enumerate(LABELS):
            p = np.array(table[t]) / sum(table[t])
            for stim in STIMULI[label]:
                for _ in range(repeats):
                    rows.append([f"L{li + 1:02d}", stim, label, LABELS[rng.choice(5, p=p)]])
    order = rng.permutation(len(rows))
    rows = [rows[i] for i in order]
    with open(path, "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")  # quotes stimuli with commas and doubles quotes
        w.writerow(["listener", "stimulus", "material", "answer"])
        w.writerows(rows)
    return [r[2] for r in rows], [r[3] for r in rows]


truth_rec, resp_rec = draw("responses_recorded.csv", TABLE_III, 30, 2)
truth_syn, resp_syn = draw("responses_synthesised.csv", TABLE_IV, 25, 3)


def summary(truth, resp):
    cm = confusion_matrix(truth, resp, labels=LABELS)
    keep_r = cm.sum(axis=1) > 0
    keep_c = cm.sum(axis=0) > 0
    chi2, p, dof, _ = chi2_contingency(cm[keep_r][:, keep_c])
    pct = 100.0 * cm / cm.sum(axis=1, keepdims=True)
    return {"counts": cm.tolist(), "row_percent": pct.tolist(),
            "accuracy": accuracy_score(truth, resp),
            "recall": recall_score(truth, resp, labels=LABELS, average=None).tolist(),
            "kappa": cohen_kappa_score(truth, resp, labels=LABELS),
            "chi2": chi2, "chi2_df": int(dof), "chi2_p": p}


rec, syn = summary(truth_rec, resp_rec), summary(truth_syn, resp_syn)


def newcombe(x1, n1, x2, n2):
    a = binomtest(x1, n1).proportion_ci(0.95, method="wilson")
    b = binomtest(x2, n2).proportion_ci(0.95, method="wilson")
    p1, p2 = x1 / n1, x2 / n2
    d = p1 - p2
    return [d - np.sqrt((p1 - a.low) ** 2 + (b.high - p2) ** 2),
            d + np.sqrt((a.high - p1) ** 2 + (p2 - b.low) ** 2)]


cm_r, cm_s = np.array(rec["counts"]), np.array(syn["counts"])
compare = {"frobenius": float(np.linalg.norm(np.array(rec["row_percent"]) - np.array(syn["row_percent"]))),
           "recall_diff_ci": [newcombe(int(cm_r[i, i]), int(cm_r[i].sum()), int(cm_s[i, i]), int(cm_s[i].sum()))
                              for i in range(5)]}
# A 2x2 table: scipy applies Yates' continuity correction (df = 1).
y_chi2, y_p, y_dof, _ = chi2_contingency([[12, 3], [5, 10]])
yates = {"counts": [[12, 3], [5, 10]], "chi2": y_chi2, "chi2_p": y_p, "chi2_df": int(y_dof)}
golden = {"labels": LABELS, "yates_2x2": yates, "recorded": rec, "synthesised": syn, "recorded_vs_synthesised": compare,
          "ren2013": ren,
          "versions": {"numpy": np.__version__, "scipy": scipy.__version__, "sklearn": sklearn.__version__}}
with open("golden.json", "w") as f:
    json.dump(golden, f, indent=1)
print(json.dumps(ren), compare["frobenius"])
