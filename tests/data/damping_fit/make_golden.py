#!/usr/bin/python3
"""Golden values for the EMG damping fit (tests/analysis/damping/test_damping_golden.cpp).

Writes features.csv and features_powerlaw.csv (12 synthetic strikes x 25 modes each: law + per-strike
exponential support excess + normal noise) and golden.json: for each law (rayleigh, hybrid on
features.csv; powerlaw on features_powerlaw.csv) the maximum of the EMG log-likelihood (Sterling et al.
2019, eq. 1.10) found by SciPy (BFGS then L-BFGS-B, analytic gradient, four starts).
Needs Debian packages python3-numpy python3-scipy. Run from anywhere: /usr/bin/python3 make_golden.py (Debian python, not a pyenv one)
"""
import json
import math
import os

import numpy as np
from scipy import optimize, special

HERE = os.path.dirname(os.path.abspath(__file__))
rng = np.random.default_rng(20190503)

# --- features -------------------------------------------------------------------------------------
# Two data sets: features.csv from Sterling's steel (hybrid law, alpha1 = 2.4 1/s) for the rayleigh and
# hybrid fits, and features_powerlaw.csv from a pure power law for the powerlaw fit (on steel-like data
# with an intercept, the powerlaw EMG optimum lies on the boundary sigma -> 0: not a useful golden value).
DATASETS = {
    "features.csv": (2.4, 5.5e-8, 1.011),           # Sterling 2019 steel, hybrid; c = 2d, lambda (rad/s)^2
    "features_powerlaw.csv": (0.0, 4.3e-4, 0.6),    # c ~ 1 1/s at 100 Hz, ~300 1/s at 15 kHz
}
LAWS = {"features.csv": ["rayleigh", "hybrid"], "features_powerlaw.csv": ["powerlaw"]}


def write_features(name, alpha1, alpha2, alpha3):
    rows = []
    for sound in range(12):
        omega = 2 * np.pi * np.exp(rng.uniform(np.log(100.0), np.log(15000.0), 25))
        lam = omega ** 2
        c = alpha1 + alpha2 * lam ** alpha3
        c = c + rng.exponential(rng.uniform(0.5, 3.0), lam.size) + rng.normal(0.0, 0.2, lam.size)
        d = np.maximum(c, 0.05) / 2
        f = np.sqrt(lam - d ** 2) / (2 * np.pi)
        amp = rng.uniform(0.05, 1.0, lam.size)
        rows += [(f"strike{sound:02d}", fi, di, ai) for fi, di, ai in zip(f, d, amp)]
    with open(os.path.join(HERE, name), "w") as out:
        out.write("# written by make_golden.py\nsound,freq_hz,decay_per_s,amp\n")
        for s, fi, di, ai in rows:
            out.write(f"{s},{float(fi)!r},{float(di)!r},{float(ai)!r}\n")


def read_points(name):
    """(lambda, c) from the decimal strings written, exactly as the C++ reader sees them."""
    freq, decay = [], []
    with open(os.path.join(HERE, name)) as inp:
        for line in inp:
            if line.startswith("#") or line.startswith("sound"):
                continue
            _, fi, di, _ = line.strip().split(",")
            freq.append(float(fi))
            decay.append(float(di))
    freq, decay = np.array(freq), np.array(decay)
    return (2 * np.pi * freq) ** 2 + decay ** 2, 2 * decay


# --- EMG likelihood in physical units, log erfc via log_ndtr: erfc(s) = 2 Phi(-sqrt2 s) ---------------
# Globals of the current data set (set in the loop below): lam, c and their scaled x = lam/L0, y = c/C0
# (L0 = max lambda, C0 = median c: conditioning only; the likelihood is reported physically).


def unpack(theta, law):
    if law == "rayleigh":
        a, b, p = theta[0], theta[1], 1.0
    elif law == "powerlaw":
        a, b, p = 0.0, theta[0], theta[1]
    else:
        a, b, p = theta[0], theta[1], theta[2]
    return a, b, p, math.exp(theta[-2]), math.exp(theta[-1])


def physical(theta, law):
    a, b, p, sig, eta = unpack(theta, law)
    return dict(alpha1=C0 * a, alpha2=C0 * b / L0 ** p, alpha3=p, sigma=C0 * sig, eta=eta / C0)


def loglik_physical(pp):
    model = pp["alpha1"] + pp["alpha2"] * lam ** pp["alpha3"]
    sig, eta = pp["sigma"], pp["eta"]
    s = (model + eta * sig ** 2 - c) / (math.sqrt(2) * sig)
    log_erfc = math.log(2) + special.log_ndtr(-math.sqrt(2) * s)
    return float(np.sum(np.log(eta / 2) + eta / 2 * (2 * model + eta * sig ** 2 - 2 * c) + log_erfc))


def negll(theta, law):
    a, b, p, sig, eta = unpack(theta, law)
    m = a + b * x ** p
    s = (m + eta * sig ** 2 - y) / (math.sqrt(2) * sig)
    log_erfc = math.log(2) + special.log_ndtr(-math.sqrt(2) * s)
    return -float(np.sum(np.log(eta / 2) + eta * (m - y) + eta ** 2 * sig ** 2 / 2 + log_erfc))


def negll_grad(theta, law):
    a, b, p, sig, eta = unpack(theta, law)
    px = x ** p
    m = a + b * px
    r = y - m
    s = (eta * sig ** 2 - r) / (math.sqrt(2) * sig)
    t = -2 / (math.sqrt(math.pi) * special.erfcx(s))   # d log erfc / ds
    l_m = eta + t / (math.sqrt(2) * sig)
    g_lsig = np.sum(eta ** 2 * sig ** 2 + t * (eta * sig / math.sqrt(2) + r / (math.sqrt(2) * sig)))
    g_leta = np.sum(1 - eta * r + eta ** 2 * sig ** 2 + t * eta * sig / math.sqrt(2))
    dm = {"a": np.ones_like(x), "b": px, "p": b * px * np.log(x)}
    names = {"rayleigh": ["a", "b"], "powerlaw": ["b", "p"], "hybrid": ["a", "b", "p"]}[law]
    g = [np.sum(l_m * dm[k]) for k in names] + [g_lsig, g_leta]
    return -np.array(g)


def starts(law):
    # Least squares of the law (scipy curve_fit), lines shifted down, and spreads of the residuals.
    f = {"rayleigh": lambda xx, a, b: a + b * xx, "powerlaw": lambda xx, b, p: b * xx ** p,
         "hybrid": lambda xx, a, b, p: a + b * xx ** p}[law]
    p0 = {"rayleigh": [0.1, 1.0], "powerlaw": [1.0, 1.0], "hybrid": [0.1, 1.0, 1.0]}[law]
    coef, _ = optimize.curve_fit(f, x, y, p0=p0, maxfev=20000)
    spread = np.std(y - f(x, *coef))
    out = []
    for shift, sig_frac, eta_mult in [(0.0, 0.5, 1.0), (1.0, 0.1, 1.0), (0.5, 0.3, 2.0), (1.5, 1.0, 0.5)]:
        th = list(coef)
        if law != "powerlaw":
            th[0] -= shift * spread
        else:
            th[0] *= 1 - 0.1 * shift
        out.append(np.array(th + [math.log(sig_frac * spread), math.log(eta_mult / spread)]))
    return out


golden = {"source": "make_golden.py (scipy %s, numpy %s)" % (__import__("scipy").__version__, np.__version__)}
for name, law_params in DATASETS.items():
    write_features(name, *law_params)
for name in DATASETS:
    lam, c = read_points(name)
    L0, C0 = lam.max(), np.median(c)
    x, y = lam / L0, c / C0
    for law in LAWS[name]:
        best = None
        for th0 in starts(law):
            res = optimize.minimize(negll, th0, args=(law,), jac=negll_grad, method="BFGS",
                                    options={"gtol": 1e-10, "maxiter": 20000})
            res = optimize.minimize(negll, res.x, args=(law,), jac=negll_grad, method="L-BFGS-B",
                                    options={"ftol": 1e-15, "gtol": 1e-12, "maxiter": 20000})
            if best is None or res.fun < best.fun:
                best = res
        pp = physical(best.x, law)
        pp["loglik"] = loglik_physical(pp)
        pp["gradient_norm_scaled"] = float(np.linalg.norm(negll_grad(best.x, law)))
        pp["features"] = name
        pp["points"] = int(lam.size)
        if law == "powerlaw":
            pp["alpha1"] = 0.0
        golden[law] = pp
        print(law, pp)

with open(os.path.join(HERE, "golden.json"), "w") as out:
    json.dump(golden, out, indent=2)
    out.write("\n")
