#!/usr/bin/env python3
"""Viscoelastic Hertz restitution (Kuwabara & Kono 1987; Ramirez et al. 1999; Muller &
Poschel 2011): the Pade form e(v*) and the two-term series, v* = beta^(1/2) v^(1/10).
Independent of the C++ oracles: plain Python floats.

Usage: python3 reference_data/generate_kuwabara_kono_pade.py > reference_data/kuwabara_kono_pade.csv
"""

ROWS = 41  # v* = 10^(-3 + 4 i/40), i = 0..40: log-spaced from 1e-3 to 10

NUM = [1.0, 1.07232, 0.574198, 0.141552]
DEN = [1.0, 1.07232, 1.72765, 1.37842, 1.19449, 0.467273, 0.235585]


def poly(coeffs, x):
    return sum(c * x ** k for k, c in enumerate(coeffs))


def pade(v):
    return poly(NUM, v) / poly(DEN, v)


def series(v):
    # 1 - e = 1.15344 beta v^(1/5) - 0.79826 beta^2 v^(2/5), and beta v^(1/5) = v*^2
    return 1.0 - 1.15344 * v ** 2 + 0.79826 * v ** 4


print("v_star,e_pade,e_series")
for i in range(ROWS):
    v = 10.0 ** (-3.0 + 4.0 * i / (ROWS - 1))
    print("%.12e,%.12e,%.12e" % (v, pade(v), series(v)))
