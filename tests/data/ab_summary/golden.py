#!/usr/bin/env python3
"""Golden values of ab_summary (tests/analysis/stats/test_ab_summary.cpp), Python standard library only:
statistics.NormalDist().inv_cdf is z, math.comb gives the exact binomial tail.
Writes golden.json; the trials are the ones test_ab_summary.cpp builds."""
import json, math
from statistics import NormalDist

z = NormalDist().inv_cdf
out = {}
# yes-no: 10 signal trials with 7 yes, 10 noise trials with 2 yes.
H, F = 7 / 10, 2 / 10
out["yesno"] = {"hits": 7, "false_alarms": 2, "dprime": z(H) - z(F), "criterion_c": -(z(H) + z(F)) / 2}
# yes-no with every signal trial answered yes: H = 1 - 1/(2*8) (Macmillan & Kaplan 1985), F = 3/8.
H2, F2 = 1 - 1 / 16, 3 / 8
out["yesno_corrected"] = {"dprime": z(H2) - z(F2), "criterion_c": -(z(H2) + z(F2)) / 2}
# 2AFC: 15 correct of 20; d' = sqrt2 z(pc); one-sided exact binomial p of k >= 15 at 1/2.
k, n = 15, 20
out["2afc"] = {"correct": k, "pc": k / n, "dprime": math.sqrt(2) * z(k / n),
               "p_above_chance": sum(math.comb(n, i) for i in range(k, n + 1)) / 2**n}
# preference: A 6, B 2, 2 ties; two-sided exact binomial p at 1/2 (symmetric: twice the tail).
a, b = 6, 2
out["preference"] = {"first": a, "second": b, "ties": 2,
                     "p": min(1.0, 2 * sum(math.comb(a + b, i) for i in range(a, a + b + 1)) / 2**(a + b))}
json.dump(out, open(__file__.replace("golden.py", "golden.json"), "w"), indent=1)
