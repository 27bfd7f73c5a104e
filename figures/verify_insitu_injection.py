"""Borehole injection under an in-situ far field: the broken beams and the borehole pressure.

--data: a folder of run folders as `hmlattice run` writes them (config.toml with [mechanics] S_H, S_h,
theta_H; breaks.csv; series.csv), e.g. the lattice2d.insitu_injection benchmark's data folder or
out/ holding runs of cases/insitu_*_quick.toml. One panel per run: its broken beams (colour: time of
breaking), the borehole and the S_H direction; a last panel: p_h(t) of every run, with each run's
Hubbert-Willis pressure 3 S_h - S_H + T_u as a dashed line.
"""
import os
import tomllib

import matplotlib.pyplot as plt
import numpy as np

import hmplot

args = hmplot.arguments(__doc__, check=lambda a: hmplot.runs_problem(a.data))
runs = hmplot.runs_to_draw(args.data)

# A grid of at most three panels a row (one row of six was a 3780 px strip in the report).
n_panels = len(runs) + 1
n_cols = min(3, n_panels)
n_rows = -(-n_panels // n_cols)
fig, grid = plt.subplots(n_rows, n_cols, figsize=(4.2 * n_cols, 4.2 * n_rows), squeeze=False)
axes = list(grid.flat)[:n_panels]
for ax in list(grid.flat)[n_panels:]:
    ax.axis("off")
for k, ((label, folder), ax) in enumerate(zip(runs, axes)):
    with open(os.path.join(folder, "config.toml"), "rb") as f:
        config = tomllib.load(f)
    mech, physics = config["mechanics"], config["physics"]
    breaks = hmplot.read_break_log(os.path.join(folder, "breaks.csv"))
    points = ax.scatter(breaks["x"], breaks["y"], c=breaks["time"], s=3, cmap="viridis")
    if mech.get("S_H", 0.0) > mech.get("S_h", 0.0):  # isotropic: no direction to draw
        theta = np.radians(mech.get("theta_H", 0.0))
        ax.plot([-np.cos(theta), np.cos(theta)], [-np.sin(theta), np.sin(theta)], "r--", lw=1, label="S_H direction")
        ax.legend(loc="lower right", fontsize=8)
    phi = np.linspace(0, 2 * np.pi, 200)
    ax.plot(physics["R_i"] * np.cos(phi), physics["R_i"] * np.sin(phi), "k-", lw=0.8)
    ax.plot(np.cos(phi), np.sin(phi), "k-", lw=0.8)
    ax.set(aspect="equal", xlim=(-1.05, 1.05), ylim=(-1.05, 1.05), xlabel="$x/R$", ylabel="$y/R$",
           title=f"{label}\nS_H = {mech.get('S_H', 0):.1e}, S_h = {mech.get('S_h', 0):.1e}")
    fig.colorbar(points, ax=ax, shrink=0.7, label="t* of breaking")
    series = hmplot.read_csv(os.path.join(folder, "series.csv"))
    colour = f"C{k}"
    axes[-1].plot(series["t"], series["p_h"], color=colour, label=label)
    p_hw = 3 * mech.get("S_h", 0.0) - mech.get("S_H", 0.0) + physics["tensile_strength"]
    axes[-1].axhline(p_hw, color=colour, ls="--", lw=1)
axes[-1].set(xscale="log", xlabel="$t^*$", ylabel="$p_h/E$", title="borehole pressure (dashed: Hubbert–Willis)")
axes[-1].legend(fontsize=8)
hmplot.provenance_footer(fig, [folder for _, folder in runs])
hmplot.save(fig, args.out, "verify_insitu_injection")
