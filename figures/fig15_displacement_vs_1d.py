"""Fig. 15 of Ulven & Sun (2017): radially averaged radial displacement of the fracturing lattice with
fast flow in fractures (the paper's Q = 0.01, iota = 1e3) against the 1D model without fracture, b = 0.2
(left) and b = 0.8 (right), at Fig. 15's times. Each panel is titled with its run's setting from its
config.toml (INCOMPLETE for a run that stopped early); the footer names the cases and the build.

Reads radial.csv and breakdown.csv of the Fig. 14 runs (one run folder, or a folder of run folders: one
panel each, in order of b) and, with --fdm1d, profiles.csv of `hmlattice fdm1d` at the same times (one
fdm1d folder, or a folder of them: each run is drawn against the one with its b):

    build/hmlattice fdm1d cases/fig15_fdm1d_b0.2.toml --out out/fig15_fdm1d/b0.2
    build/hmlattice fdm1d cases/fig15_fdm1d_b0.8.toml --out out/fig15_fdm1d/b0.8
    /usr/bin/python3 figures/fig15_displacement_vs_1d.py --data out/fig14 --fdm1d out/fig15_fdm1d --out out/fig14/figures

Prints, per run, how many of its output times have a 1D profile to compare with. The curves are drawn
as Fig. 13's (hmplot.draw_displacement_vs_1d): solid with markers the lattice's shell means of u_r,
dashed fdm1d's nodal u_r at the same time, each labelled unbroken or fractured at that time. Without
--fdm1d, a benchmark's data folder (runs.csv) names each run's 1D folder.
"""
import os

import hmplot
from hmplot import plt


def check(args):
    """Why these arguments cannot be drawn, or None."""
    problem = hmplot.runs_problem(args.data)
    if problem or not args.fdm1d:
        return problem
    if not os.path.isdir(args.fdm1d) or not hmplot.fdm1d_folders(args.fdm1d):
        return (f"--fdm1d = {args.fdm1d}: allowed: a folder `hmlattice fdm1d` wrote (profiles.csv) or a folder of "
                "such folders")
    return None


def main():
    args = hmplot.arguments(__doc__.splitlines()[0], lambda parser: parser.add_argument(
        "--fdm1d", help="an `hmlattice fdm1d` folder at the runs' output times, or a folder of them (matched by b)"),
        check)
    runs = hmplot.runs_to_draw(args.data)
    by_b = hmplot.fdm1d_folders(args.fdm1d)
    # A benchmark's data folder (runs.csv) names each run's 1D reference.
    indexed = hmplot.indexed_folders(args.data, "fdm1d")
    fig, axes = plt.subplots(1, len(runs), figsize=(5.2 * len(runs), 3.9), squeeze=False)
    for col, (label, folder) in enumerate(runs):
        b = hmplot.run_physics(folder, "b")
        title = f"b = {b:g}" if b is not None else label
        # One 1D folder given for one run is its reference whatever its b; otherwise match by b.
        folder_1d = next(iter(by_b.values())) if len(by_b) == 1 and len(runs) == 1 else by_b.get(b)
        if not args.fdm1d:
            folder_1d = indexed.get(label)
        t_first = hmplot.read_csv(os.path.join(folder, "breakdown.csv"))["t_first_break"][0]
        ax = axes[0][col]
        n_times, n_compared = hmplot.draw_displacement_vs_1d(ax, folder, folder_1d, t_first)
        print(f"fig15: {title}: {n_times} output times, {n_compared} with a 1D profile")
        ax.set_title(hmplot.run_title(folder, label) + "\n$u_r$: lattice (solid), 1D without fracture (dashed)",
                     fontsize=8)
        ax.legend(loc="best", fontsize=7)
    fig.suptitle("Fig. 15 of Ulven & Sun (2017): radially averaged $u_r$\neach panel's setting from its config.toml",
                 fontsize=9)
    footer = hmplot.provenance_footer(fig, [folder for _, folder in runs])
    fig.set_layout_engine("tight", rect=(0, footer + 0.01, 1, 1))  # room for the footer
    hmplot.save(fig, args.out, "fig15_displacement_vs_1d")


if __name__ == "__main__":
    main()
