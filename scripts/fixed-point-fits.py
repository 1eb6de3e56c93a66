#!/usr/bin/python3
"""Polynomial coefficients of tread's fixed-point elementary functions (src/fixed/q_math.cpp).

Each function is fitted on its reduced interval by iteratively reweighted least squares on
Chebyshev nodes (a Lawson iteration toward the minimax fit), then rounded to Q1.30. Prints the
C++ arrays and the fit's own maximum error on a dense grid (before the Q30 rounding of the
evaluation, which dominates: one step is 9.3e-10). Run: /usr/bin/python3 scripts/fixed-point-fits.py
"""
import numpy as np


def fit(f, basis, a, b, degrees, nodes=3000, iterations=300):
    k = np.arange(nodes)
    x = (a + b) / 2 + (b - a) / 2 * np.cos(np.pi * (k + 0.5) / nodes)
    A = np.stack([basis(x, d) for d in degrees], 1)
    y = f(x)
    c, *_ = np.linalg.lstsq(A, y, rcond=None)
    w = np.ones(nodes)
    for _ in range(iterations):
        w = w * (np.abs(A @ c - y) + 1e-300)
        w /= w.sum()
        sw = np.sqrt(w)
        c, *_ = np.linalg.lstsq(A * sw[:, None], y * sw, rcond=None)
    xx = np.linspace(a, b, 400001)
    AA = np.stack([basis(xx, d) for d in degrees], 1)
    return c, float(np.max(np.abs(AA @ c - f(xx))))


def odd(u, d):
    return u ** (2 * d + 1)


def even(u, d):
    return u ** (2 * d)


def power(u, d):
    return u ** d


FITS = [
    ("kAtan", "atan(u) = u·P(u²), |u| ≤ tan(π/8)", np.arctan, odd, 0.0, np.tan(np.pi / 8), 7),
    ("kSin", "sin(r) = r·P(r²), |r| ≤ π/4", np.sin, odd, 0.0, np.pi / 4, 5),
    ("kCos", "cos(r) = P(r²), |r| ≤ π/4", np.cos, even, 0.0, np.pi / 4, 5),
    ("kExp2", "2^f = P(f), f ∈ [0, 1)", lambda f: 2.0 ** f, power, 0.0, 1.0, 8),
    ("kAtanh", "atanh(s) = s·P(s²), |s| ≤ 3 − 2√2", np.arctanh, odd, 0.0, 3 - 2 * np.sqrt(2), 6),
]

for name, what, f, basis, a, b, n in FITS:
    c, err = fit(f, basis, a, b, range(n))
    q30 = [int(round(v * 2 ** 30)) for v in c]
    print(f"// {what}; fit error {err:.2e}")
    print(f"constexpr std::array<std::int64_t, {n}> {name}{{{', '.join(map(str, q30))}}};")
