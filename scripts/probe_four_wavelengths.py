#!/usr/bin/env python3
"""How close can four wavelengths come to the ColorChecker under D65? (issue 16, README
"Optimised wavelength sets").

An upper bound on what any 4-wavelength set with a 3 x 4 matrix can do, independent of Prism's own
fit (spectral/wavelength_fit.cpp) and of its ΔE00 code: fitted on the chart alone (training set =
test set), the matrix minimising the mean CIEDE2000 itself (not a linearised least squares), the
wavelengths continuous. Every combination of a 10 nm grid over 380-780 nm is screened with its
least-squares matrix; the best starts are then refined jointly (4 wavelengths + 12 weights) by
Powell and Nelder-Mead. Reads data/ (CIE 1931 2°, D65, ColorChecker, Sharma's CIEDE2000 pairs
to check its own formula first). Needs Debian's
python3-numpy and python3-scipy. About 5 minutes on 2 cores with 30 starts.

Usage: scripts/probe_four_wavelengths.py [STARTS]
"""
import csv
import itertools
import pathlib
import sys

import numpy as np
from scipy.optimize import minimize

DATA = pathlib.Path(__file__).resolve().parent.parent / "data"
LAMBDA = np.arange(360, 831)


def table(name):
    rows = list(csv.reader(open(DATA / name)))
    return rows[0], np.array([[float(v) for v in row] for row in rows[1:]])


def resample(x, y):  # linear, ends held
    return np.interp(LAMBDA, x, y)


_, cmf = table("cie1931_2deg.csv")
header, illuminants = table("cie_illuminants_A_D65_1nm.csv")
_, chart = table("colorchecker24.csv")
XYZ_BAR = np.stack([resample(cmf[:, 0], cmf[:, c]) for c in (1, 2, 3)])
D65 = resample(illuminants[:, 0], illuminants[:, header.index("D65")])
LIGHT = D65 / (XYZ_BAR[1] @ D65)
WHITE = XYZ_BAR @ LIGHT
RADIANCE = np.stack([resample(chart[:, 0], chart[:, i]) for i in range(1, 25)]) * LIGHT
TRUTH = RADIANCE @ XYZ_BAR.T


def lab(xyz):
    t = xyz / WHITE
    d = 6 / 29
    f = np.where(t > d**3, np.cbrt(np.maximum(t, 1e-30)), t / (3 * d * d) + 4 / 29)
    return np.stack([116 * f[:, 1] - 16, 500 * (f[:, 0] - f[:, 1]), 200 * (f[:, 1] - f[:, 2])], 1)


def ciede2000(lab1, lab2):  # Sharma, Wu and Dalal (2005)
    l1, a1, b1 = lab1.T
    l2, a2, b2 = lab2.T
    cbar = (np.hypot(a1, b1) + np.hypot(a2, b2)) / 2
    g = 0.5 * (1 - np.sqrt(cbar**7 / (cbar**7 + 25.0**7)))
    a1p, a2p = (1 + g) * a1, (1 + g) * a2
    c1p, c2p = np.hypot(a1p, b1), np.hypot(a2p, b2)
    h1p = np.degrees(np.arctan2(b1, a1p)) % 360
    h2p = np.degrees(np.arctan2(b2, a2p)) % 360
    zero = c1p * c2p == 0
    dh = h2p - h1p
    dh = np.where(dh > 180, dh - 360, np.where(dh < -180, dh + 360, dh))
    dh = np.where(zero, 0, dh)
    dhp = 2 * np.sqrt(c1p * c2p) * np.sin(np.radians(dh / 2))
    lbar, cbarp, hsum = (l1 + l2) / 2, (c1p + c2p) / 2, h1p + h2p
    hbar = np.where(zero, hsum, np.where(np.abs(h1p - h2p) <= 180 + 1e-9, hsum / 2,
                                         np.where(hsum < 360, (hsum + 360) / 2, (hsum - 360) / 2)))
    t = (1 - 0.17 * np.cos(np.radians(hbar - 30)) + 0.24 * np.cos(np.radians(2 * hbar))
         + 0.32 * np.cos(np.radians(3 * hbar + 6)) - 0.2 * np.cos(np.radians(4 * hbar - 63)))
    rc = 2 * np.sqrt(cbarp**7 / (cbarp**7 + 25.0**7))
    rt = -np.sin(np.radians(60 * np.exp(-(((hbar - 275) / 25) ** 2)))) * rc
    sl = 1 + 0.015 * (lbar - 50) ** 2 / np.sqrt(20 + (lbar - 50) ** 2)
    sc, sh = 1 + 0.045 * cbarp, 1 + 0.015 * cbarp * t
    dl, dc, dhh = (l2 - l1) / sl, (c2p - c1p) / sc, dhp / sh
    return np.sqrt(dl**2 + dc**2 + dhh**2 + rt * dc * dhh)


TRUTH_LAB = lab(TRUTH)


def samples(wavelengths):  # 24 x 4: each patch's radiance at the wavelengths
    return np.stack([np.interp(wavelengths, LAMBDA, r) for r in RADIANCE])


def mean_error(weights, s):
    return ciede2000(TRUTH_LAB, lab(s @ weights.T)).mean()


def least_squares(s):
    return np.linalg.lstsq(s, TRUTH, rcond=None)[0].T


def objective(x):
    wavelengths = np.sort(x[:4])
    if wavelengths[0] < 360 or wavelengths[-1] > 830:
        return np.inf
    return mean_error(x[4:].reshape(3, 4), samples(wavelengths))


def refine(start):
    s = samples(np.array(start, float))
    best = np.concatenate([start, least_squares(s).ravel()])
    value = objective(best)
    while True:
        r = minimize(objective, best, method="Powell", options={"maxiter": 20000, "xtol": 1e-6, "ftol": 1e-10})
        r = minimize(objective, r.x, method="Nelder-Mead",
                     options={"maxiter": 40000, "xatol": 1e-8, "fatol": 1e-11, "adaptive": True})
        if r.fun >= value - 1e-6:
            return value, np.sort(best[:4])
        value, best = r.fun, r.x


def check_ciede2000():  # against Sharma's 34 published pairs, as Prism's own formula is
    _, pairs = table("ciede2000_sharma.csv")
    worst = np.abs(ciede2000(pairs[:, 1:4], pairs[:, 4:7]) - pairs[:, 7]).max()
    if worst > 1e-4:
        sys.exit(f"this probe's CIEDE2000 is {worst:.2e} off Sharma's pairs (data/ciede2000_sharma.csv)")


def main():
    check_ciede2000()
    starts = int(sys.argv[1]) if len(sys.argv) > 1 else 30
    grid = np.arange(380, 781, 10)
    screened = sorted((mean_error(least_squares(samples(np.array(c, float))), samples(np.array(c, float))), c)
                      for c in itertools.combinations(grid, 4))
    print(f"screened {len(screened)} sets; best with its least-squares matrix: {screened[0][0]:.3f} at {screened[0][1]} nm")
    results = []
    for k, (_, start) in enumerate(screened[:starts]):
        results.append(refine(np.array(start, float)))
        bar = "#" * (20 * (k + 1) // starts)
        print(f"\r[{bar:<20}] {k + 1}/{starts}  best so far {min(results)[0]:.4f}", end="", flush=True)
    value, wavelengths = min(results, key=lambda r: r[0])
    print(f"\nlowest mean ΔE00 over the chart: {value:.3f} at {np.round(wavelengths, 1)} nm (the issue asks ≤ 0.5)")


if __name__ == "__main__":
    main()
