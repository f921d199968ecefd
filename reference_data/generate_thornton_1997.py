#!/usr/bin/env python3
"""Thornton (1997) coefficient of restitution e(r), r = V_y/V_i, for elastic-perfectly
plastic spheres (J. Appl. Mech. 64:383-386). Independent of the C++ oracles: plain Python
floats and the math module.

Usage: python3 reference_data/generate_thornton_1997.py > reference_data/thornton_1997.csv
"""
import math

ROWS = 40          # r = 10^(-4 i/39), i = 0..39: log-spaced from 1 down to 1e-4
DECADES = 4.0


def thornton(r):
    if r >= 1.0:
        return 1.0
    return (math.sqrt(6.0 * math.sqrt(3.0) / 5.0) * math.sqrt(1.0 - r * r / 6.0)
            * (r / (r + 2.0 * math.sqrt(6.0 / 5.0 - r * r / 5.0))) ** 0.25)


print("r,e_thornton")
for i in range(ROWS):
    r = 10.0 ** (-DECADES * i / (ROWS - 1))
    print("%.12e,%.12e" % (r, thornton(r)))
