"""Verification figure: uniaxial tension of the dry lattice to failure (benchmark lattice2d.uniaxial_tension).

Reads lattice2d_uniaxial_tension.csv (strain, mean_stress, n_broken, next_break_strain; one row per load
step) and lattice2d_uniaxial_tension_breaks.csv (the break log: x, y, strain, sigma_1, ..., mode).
Left: mean stress / T_u against strain. Right: the broken beams' midpoints, coloured by break order.
"""
import os

import matplotlib.pyplot as plt

import hmplot

T_U = 2e-4  # Table 1 T_u/E, the benchmark's mean strength


args = hmplot.arguments(__doc__)
steps = hmplot.read_csv(os.path.join(args.data, "lattice2d_uniaxial_tension.csv"))
breaks = hmplot.read_break_log(os.path.join(args.data, "lattice2d_uniaxial_tension_breaks.csv"))

fig, axes = plt.subplots(1, 2, figsize=(9, 3.8))
axes[0].plot(steps["strain"], steps["mean_stress"] / T_U, "-", marker=".", ms=3)
axes[0].axhline(1.0, color="k", ls="--", lw=0.8, label="T_u")
axes[0].set(xlabel="applied strain", ylabel="mean stress / T_u", title="load-displacement (snapped to breaks)")
axes[0].legend()
sc = axes[1].scatter(breaks["x"], breaks["y"], c=breaks["sequence"], s=4, cmap="viridis")
axes[1].set(xlim=(-0.5, 0.5), ylim=(-0.5, 0.5), aspect="equal", xlabel="x", ylabel="y",
            title=f"broken beams ({len(breaks['x'])}), load along y")
fig.colorbar(sc, ax=axes[1], label="break order")
hmplot.save(fig, args.out, "verify_lattice_uniaxial", sources=[args.data])
