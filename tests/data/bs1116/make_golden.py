# Golden values for the BS.1116 summary (tests/analysis/stats/test_bs1116.cpp, tests/cli/test_cli_stats.cpp).
# A seeded BS.1116 result set (8 assessors x 3 conditions x 2 repeats, one assessor who cannot tell the
# hidden reference), written as the tidy export's bs1116.csv, then with SciPy: per condition the mean over
# assessors of each assessor's mean difference grade, its sample sd and t-based 95 % interval
# (scipy.stats.t.ppf); per assessor the trials with a positive difference grade and a one-sided one-sample
# t-test of their difference grades against 0 (scipy.stats.ttest_1samp, alternative='less').
# Run from this folder with Debian's python3-scipy: /usr/bin/python3 make_golden.py
import csv
import random

import numpy as np
from scipy import stats

rng = random.Random(1116)
impairment = {"codec_a": -0.4, "codec_b": -1.3, "lowpass": -2.6}
rows = []
for a in range(8):
    subject = f"L{a + 1}"
    for rep in range(2):
        for condition, shift in impairment.items():
            hidden = round(min(5.0, max(1.0, 4.9 + rng.gauss(0, 0.15))), 1)
            if subject == "L8":  # cannot tell: the condition graded like the hidden reference, either side
                graded = round(min(5.0, max(1.0, hidden + rng.gauss(0, 0.4))), 1)
            else:
                graded = round(min(5.0, max(1.0, hidden + shift + rng.gauss(0, 0.3))), 1)
            side = rng.choice("AB")
            diff = round(graded - hidden, 6)
            rows.append([subject, condition, "ref", side, graded, hidden, diff])

with open("grades.csv", "w", newline="") as f:
    w = csv.writer(f)
    w.writerow(["participant", "condition", "reference", "hidden_reference", "condition_grade", "reference_grade",
                "diffgrade"])
    w.writerows(rows)

with open("summary_golden.csv", "w", newline="") as f:
    w = csv.writer(f)
    w.writerow(["condition", "n", "mean", "sd", "ci_low", "ci_high"])
    for condition in impairment:
        per = []
        for a in range(8):
            d = [r[6] for r in rows if r[0] == f"L{a + 1}" and r[1] == condition]
            per.append(float(np.mean(d)))
        x = np.array(per)
        n, m, s = len(x), float(x.mean()), float(x.std(ddof=1))
        h = float(stats.t.ppf(0.975, n - 1)) * s / np.sqrt(n)
        w.writerow([condition, n, repr(m), repr(s), repr(m - h), repr(m + h)])

with open("screening_golden.csv", "w", newline="") as f:
    w = csv.writer(f)
    w.writerow(["subject", "trials", "positive", "mean", "t", "p_less"])
    for a in range(8):
        d = np.array([r[6] for r in rows if r[0] == f"L{a + 1}"])
        res = stats.ttest_1samp(d, 0.0, alternative="less")
        w.writerow([f"L{a + 1}", len(d), int((d > 0).sum()), repr(float(d.mean())), repr(float(res.statistic)),
                    repr(float(res.pvalue))])
