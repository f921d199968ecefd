#!/usr/bin/env python3
"""e against v0 for three damping ratios of the paper's scene, swept in parallel and plotted.

    PYTHONPATH=build/python python3 examples/python/sweep_plot.py cor.png

Needs matplotlib (Debian: python3-matplotlib); without it, says so and exits 77 (ctest: skipped).
"""
import sys

import numpy as np

import ivv

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError as error:
    print(f"sweep_plot: skipped: matplotlib is not installed ({error}); "
          "apt-get install python3-matplotlib", file=sys.stderr)
    sys.exit(77)

out = sys.argv[1] if len(sys.argv) > 1 else "cor.png"
scene = ivv.scene("paper")
zetas = [0.0, 0.1, 0.3]
grid = ivv.sweep(scene, v0=np.geomspace(0.05, 20, 60), zeta=zetas)

fig, ax = plt.subplots(figsize=(6, 4))
for zeta in zetas:
    mine = (grid["zeta"] == zeta) & (grid["status"] != "failed")
    ax.semilogx(grid["v0"][mine], grid["e"][mine], label=f"ζ = {zeta:g}")
ax.axvline(scene.v_yield, color="grey", linestyle=":", label="$v_y$ (undamped yield)")
ax.set_xlabel("impact velocity $v_0$ [m/s]")
ax.set_ylabel("coefficient of restitution $e$")
ax.set_title("Paper scene (Table 1): elastoplastic law")
ax.legend()
fig.tight_layout()
fig.savefig(out, dpi=120)
print(f"sweep_plot: {len(grid['v0'])} impacts, wrote {out}")
