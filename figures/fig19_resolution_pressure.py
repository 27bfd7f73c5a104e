"""Fig. 19 of Ulven & Sun (2017): pressure and fractures at t* = 2.5e-2 for Q = 0.01, iota = 1, b = 0.5
on lattices of different resolution, the number of particles in each panel's lower right corner.

Reads a sweep folder over lattice.n_particles (cases/sweep_fig19_quick.toml, cases/paper/sweep_fig19.toml):
results.csv from `hmlattice sweep collect` and one run folder per combination in runs/, as the
Snakemake workflow writes them:

    snakemake -j 2 --snakefile workflow/Snakefile --config sweep=cases/sweep_fig19_quick.toml
    /usr/bin/python3 figures/fig19_resolution_pressure.py --data out/sweeps/sweep_fig19_quick --out fig

One panel per complete run, coarsest first, at its last output time (t_end, the paper's 2.5e-2), drawn
as Fig. 12's panels (hmplot.draw_pressure_snapshot): pressure per triangle, colours on a range symmetric
about 0 (ticks at that snapshot's min and max), broken beams in black. The particle count is the lattice's (the VTK
snapshot's points), which the Poisson-disk sampling makes close to, not equal to, n_particles.
Prints how many combinations were drawn and how many were left out (runs not complete).
"""
import math

import hmplot
from hmplot import plt

KEY = "lattice.n_particles"


def main():
    args = hmplot.arguments(__doc__.splitlines()[0], check=lambda a: hmplot.sweep_problem(a.data, KEY))
    runs, skipped = hmplot.sweep_runs(args.data, KEY)
    if not runs:
        raise SystemExit(f"{args.data}: no complete run to draw ({skipped} incomplete or missing)")
    n_cols = min(3, len(runs))
    n_rows = math.ceil(len(runs) / n_cols)
    fig, axes = plt.subplots(n_rows, n_cols, figsize=(3.2 * n_cols, 3.1 * n_rows), squeeze=False)
    panel = iter("ABCDEFGHIJKLMNOPQRSTUVWXYZ")
    for k, ax in enumerate(axes.flat):
        if k >= len(runs):
            ax.axis("off")
            continue
        _, folder = runs[k]
        t, path = hmplot.vtk_snapshots(folder)[-1]
        hmplot.draw_pressure_snapshot(fig, ax, path, f"{next(panel)}: $t^* = {t:.3g}$"
                                      + hmplot.fracture_counts(hmplot.fracture_summary_at(folder, t)))
        n_points = len(hmplot.read_snapshot(path)[0])
        ax.text(0.98, 0.02, f"{n_points}", transform=ax.transAxes, ha="right", va="bottom", fontsize=8)
    b, q, iota = (hmplot.run_physics(runs[0][1], key) for key in ("b", "Q", "iota"))
    fig.suptitle(f"Fig. 19: pressure $p/E$ and broken beams per lattice resolution; $Q = {q:g}$, "
                 f"$\\iota = {iota:g}$, $b = {b:g}$", fontsize=10)
    footer = hmplot.provenance_footer(fig, [folder for _, folder in runs])
    fig.set_layout_engine("tight", rect=(0, footer + 0.01, 1, 1))  # room for the footer
    hmplot.save(fig, args.out, "fig19_resolution_pressure")
    print(f"fig19: {len(runs)} of {len(runs) + skipped} combinations drawn ({skipped} incomplete or missing)")


if __name__ == "__main__":
    main()
