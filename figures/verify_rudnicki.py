"""Verification figure: Rudnicki's line source at the paper's Fig. 7 setting.

Reads analytic_rudnicki.csv (columns vol_strain [1 = plane strain, 1/3 = Appendix A], r, p, u_r).
"""
import os

import matplotlib.pyplot as plt

import hmplot

args = hmplot.arguments(__doc__)
data = hmplot.group_by(hmplot.read_csv(os.path.join(args.data, "analytic_rudnicki.csv")), "vol_strain")
label = {1.0: "plane strain (ε_r + ε_θ)"}

fig, axes = plt.subplots(1, 2, figsize=(8, 3.2))
for f, d in data.items():
    name = label.get(f, "Appendix A (⅓(ε_r + ε_θ))")
    axes[0].plot(d["r"], d["u_r"], label=name)
    axes[1].plot(d["r"], d["p"], label=name)
axes[0].set(xlabel="$r/R$", ylabel="$u_r/R$", title="radial displacement, t* = 3e-4")
axes[1].set(xlabel="$r/R$", ylabel="$p/E$", title="pressure, t* = 3e-4")
axes[0].legend()
hmplot.save(fig, args.out, "verify_rudnicki", sources=[args.data])
