"""Fig. 20 of Ulven & Sun (2017): radially averaged radial displacement at t* = 2.5e-2 for Q = 0.01,
iota = 1, b = 0.5, one curve per lattice resolution.

Reads a sweep folder over lattice.n_particles (cases/sweep_fig19_quick.toml, cases/paper/sweep_fig19.toml):
results.csv from `hmlattice sweep collect` and one run folder per combination in runs/ (radial.csv):

    snakemake -j 2 --snakefile workflow/Snakefile --config sweep=cases/sweep_fig19_quick.toml
    /usr/bin/python3 figures/fig20_displacement_resolution.py --data out/sweeps/sweep_fig19_quick --out fig

Each curve: radial.csv's shell means of u_r (shells binned by undeformed centroid radius) at the run's
last output time (t_end, the paper's 2.5e-2), labelled with n_particles and the number of radial
fractures then (fracture_summary.csv's n_radial), since the paper explains the coarsest curve by its
fewer fractures. Prints how many combinations were drawn and how many were left out.
"""
import os

import numpy as np

import hmplot
from hmplot import plt

KEY = "lattice.n_particles"


def main():
    args = hmplot.arguments(__doc__.splitlines()[0], check=lambda a: hmplot.sweep_problem(a.data, KEY))
    runs, skipped = hmplot.sweep_runs(args.data, KEY)
    if not runs:
        raise SystemExit(f"{args.data}: no complete run to draw ({skipped} incomplete or missing)")
    fig, ax = plt.subplots(figsize=(5.0, 3.6))
    colors = plt.cm.viridis(np.linspace(0.0, 0.85, len(runs)))
    for k, (n, folder) in enumerate(runs):
        radial = hmplot.group_by(hmplot.read_csv(os.path.join(folder, "radial.csv")), "t")
        t = max(radial)
        s = hmplot.fracture_summary_at(folder, t)
        fractures = f", {int(s['n_radial'])} radial fractures" if s is not None else ""
        ax.plot(radial[t]["r_mean"], radial[t]["u_r"], "-", marker="os^Dv<>"[k % 7], ms=3, markevery=2,
                color=colors[k], label=f"$N = {n:g}${fractures} ($t^* = {t:.3g}$)")
    b, q, iota = (hmplot.run_physics(runs[0][1], key) for key in ("b", "Q", "iota"))
    ax.set_xlabel("$r/R$")
    ax.set_ylabel("radially averaged $u_r/R$")
    ax.set_xlim(0.0, 1.0)
    ax.set_title(f"Fig. 20: $u_r$ per lattice resolution; $Q = {q:g}$, $\\iota = {iota:g}$, $b = {b:g}$", fontsize=9)
    ax.legend(loc="best", fontsize=7)
    footer = hmplot.provenance_footer(fig, [folder for _, folder in runs])
    fig.set_layout_engine("tight", rect=(0, footer + 0.01, 1, 1))  # room for the footer
    hmplot.save(fig, args.out, "fig20_displacement_resolution")
    print(f"fig20: {len(runs)} of {len(runs) + skipped} combinations drawn ({skipped} incomplete or missing)")


if __name__ == "__main__":
    main()
