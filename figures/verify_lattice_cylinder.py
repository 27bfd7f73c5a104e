"""Verification figure: the thick-walled cylinder under internal pressure (benchmark lattice2d.cylinder_first_break).

Reads lattice2d_cylinder_breaks.csv (the break log of the run with +-5% strengths: x, y, pressure,
sigma_1, ..., mode). Left: the broken beams' midpoints around the borehole (R_i = 0.138), coloured by
break order, the first break marked. Right: the borehole pressure of each break over Lamé's p_crit.
"""
import os

import matplotlib.pyplot as plt
import numpy as np

import hmplot

T_U, R_I = 2e-4, 0.138
P_CRIT = T_U * (1 - R_I**2) / (1 + R_I**2)  # Lamé, free outer boundary R_o = 1


args = hmplot.arguments(__doc__)
b = hmplot.read_break_log(os.path.join(args.data, "lattice2d_cylinder_breaks.csv"))

fig, axes = plt.subplots(1, 2, figsize=(9, 3.8))
t = np.linspace(0, 2 * np.pi, 400)
axes[0].plot(R_I * np.cos(t), R_I * np.sin(t), "k-", lw=0.8)
sc = axes[0].scatter(b["x"], b["y"], c=b["sequence"], s=5, cmap="viridis")
axes[0].plot(b["x"][0], b["y"][0], "r*", ms=10, label="first break")
r = max(0.3, 1.1 * np.max(np.hypot(b["x"], b["y"])))
axes[0].set(xlim=(-r, r), ylim=(-r, r), aspect="equal", xlabel="x", ylabel="y", title="broken beams")
axes[0].legend(fontsize=7)
fig.colorbar(sc, ax=axes[0], label="break order")
axes[1].plot(b["sequence"], b["pressure"] / P_CRIT, ".", ms=3)
axes[1].axhline(1.0, color="k", ls="--", lw=0.8, label="Lamé p_crit")
axes[1].set(xlabel="break number", ylabel="borehole pressure / p_crit", title="pressure at each break")
axes[1].legend()
hmplot.save(fig, args.out, "verify_lattice_cylinder", sources=[args.data])
