#!/usr/bin/env python3
"""What each Hunt-Crossley damping map mu(e) really delivers.

For F = K x^(3/2) (1 + mu x'), the exact Newton COR with u0 = mu v0 is
    e = [1 + W0(-(1 + u0) exp(-(1 + u0)))] / u0          (W0: principal Lambert W)
For each map of SPEC section 3 and each target e, u0 = v0 mu(e_target, v0) (independent of v0)
and e_delivered is the exact e at that u0.

Independent of the C++ oracles: exact decimal arithmetic (the decimal module at 50 digits),
W0 by Halley iteration started from the branch-point series. Near the branch point -1/e
this keeps every printed digit, which double precision would not.

Usage: python3 reference_data/generate_hunt_crossley_mu_maps.py > reference_data/hunt_crossley_mu_maps.csv
"""
from decimal import Decimal as D, getcontext

getcontext().prec = 50

TARGETS = ["0.1", "0.2", "0.3", "0.4", "0.5", "0.6", "0.7", "0.8", "0.9", "0.95", "0.99"]

# mu v0 as a function of e (v0 cancels in every map)
MAPS = [
    ("hunt-crossley", lambda e: 3 * (1 - e) / 2),
    ("lankarani-nikravesh", lambda e: 3 * (1 - e * e) / 4),
    ("lee-wang", lambda e: 3 * (1 - e) / 4),
    ("gonthier", lambda e: (1 - e * e) / e),
    ("flores", lambda e: 8 * (1 - e) / (5 * e)),
    ("hu-guo", lambda e: 3 * (1 - e) / (2 * e)),
    ("gharib-hurmuzlu", lambda e: 1 / e - 1),
]


def lambert_w0(x):
    """Principal branch of w exp(w) = x for -1/e <= x < 0, by Halley iteration."""
    one = D(1)
    p2 = 2 * (one.exp() * x + 1)  # 2 (e x + 1) >= 0
    if p2 < D("0.5"):
        p = p2.sqrt()
        w = -1 + p - p * p / 3 + D(11) / 72 * p * p * p  # branch-point series
    else:
        w = x * (1 - x)  # near 0
    for _ in range(100):
        ew = w.exp()
        f = w * ew - x
        wp1 = w + 1
        step = f / (ew * wp1 - (w + 2) * f / (2 * wp1))
        w -= step
        if abs(step) < D("1e-45") * (abs(w) + D("1e-45")):
            break
    return w


def exact_cor(u0):
    arg = -(1 + u0) * (-(1 + u0)).exp()
    return (1 + lambert_w0(arg)) / u0


print("model,e_target,u0,e_delivered")
for name, mu_v0 in MAPS:
    for t in TARGETS:
        e = D(t)
        u0 = mu_v0(e)
        print("%s,%s,%.12e,%.12e" % (name, t, u0, exact_cor(u0)))
