"""Verification figure: the lattice patch test (homogeneous boundary strain).

Reads lattice_patch_test.csv (one row per interior particle of the averaging region: x, y, sigma_xx,
sigma_yy, sigma_xy and the calibrated continuum's expected_xx, expected_yy, expected_xy). Draws the
histogram of each particle stress component with the continuum value dashed; the titles give the
scatter over |sigma| = |(expected_xx, expected_yy, expected_xy)|, as the report's table does.
"""
import os

import matplotlib.pyplot as plt
import numpy as np

import hmplot

args = hmplot.arguments(__doc__)
d = hmplot.read_csv(os.path.join(args.data, "lattice_patch_test.csv"))

# The scale of the table in the report: |sigma| = norm of the continuum's (xx, yy, xy).
scale = np.sqrt(sum(d[f"expected_{c}"][0] ** 2 for c in ["xx", "yy", "xy"]))
fig, axes = plt.subplots(1, 3, figsize=(10, 3.0))
for ax, c in zip(axes, ["xx", "yy", "xy"]):
    s = d[f"sigma_{c}"]
    ax.hist(s, bins=60, color="C0", alpha=0.8)
    ax.axvline(d[f"expected_{c}"][0], color="k", ls="--", label="continuum")
    ax.axvline(np.mean(s), color="C3", lw=1, label="particle mean")
    ax.set(xlabel=f"σ_{c}*", ylabel="particles", title=f"σ_{c}: sd / |σ| = {np.std(s) / scale:.2f}")
    ax.legend()
hmplot.save(fig, args.out, "verify_lattice_patch", sources=[args.data])
