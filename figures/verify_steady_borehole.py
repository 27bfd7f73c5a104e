"""Verification figure: the corrected steady-state borehole solution (Appendix B).

Reads analytic_steady_borehole.csv (columns b, r, p, u_r, sigma_r, sigma_theta, sigma_z).
"""
import os

import matplotlib.pyplot as plt

import hmplot

args = hmplot.arguments(__doc__)
data = hmplot.group_by(hmplot.read_csv(os.path.join(args.data, "analytic_steady_borehole.csv")), "b")

fig, axes = plt.subplots(1, 3, figsize=(10, 3.2))
for b, d in data.items():
    axes[0].plot(d["r"], d["p"], label=f"b = {b:g}")
    axes[1].plot(d["r"], d["u_r"], label=f"b = {b:g}")
    line, = axes[2].plot(d["r"], d["sigma_theta"], label=f"σθ, b = {b:g}")
    axes[2].plot(d["r"], d["sigma_r"], "--", color=line.get_color(), label=f"σr, b = {b:g}")
axes[0].set(xlabel="$r/R$", ylabel="$p/E$", title="pressure (B3, b-independent)")
axes[1].set(xlabel="$r/R$", ylabel="$u_r/R$", title="radial displacement (corrected B6)")
axes[2].set(xlabel="$r/R$", ylabel="effective stress $\\sigma'/E$", title="$\\sigma'_\\theta$ (solid), $\\sigma'_r$ (dashed)")
axes[1].legend()
axes[2].legend(ncol=2, fontsize=6)
hmplot.save(fig, args.out, "verify_steady_borehole", sources=[args.data])
