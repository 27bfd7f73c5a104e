"""Fig. 13 of Ulven & Sun (2017): radially averaged radial displacement of the fracturing lattice against
the 1D model without fracture (the paper's Q = 0.01, iota = 1), b = 0.2 (left) and b = 0.8 (right); below,
the borehole pressure history of both with the first break marked. Each column is titled with its run's
setting from its config.toml (INCOMPLETE for a run that stopped early); the footer names the cases and
the build.

Reads a folder with runs.csv written by the lattice2d.fig12 benchmarks (run folders as `hmlattice run`
writes them: radial.csv, series.csv, breakdown.csv; 1D folders as `hmlattice fdm1d` writes them:
profiles.csv, borehole.csv), or a run folder or a folder of run folders (one column each, in order of
b), with the 1D curves when --fdm1d names an `hmlattice fdm1d` folder at the runs' output times
(cases/fig13_fdm1d_b*.toml) or a folder of them (each run drawn against the one with its b):

    /usr/bin/python3 figures/fig13_displacement_vs_1d.py --data verify/data/fig12_quick --out fig
    /usr/bin/python3 figures/fig13_displacement_vs_1d.py --data out/fig12_b0.2 --fdm1d out/fig13_fdm1d_b0.2 --out fig
    /usr/bin/python3 figures/fig13_displacement_vs_1d.py --data out/fig12 --fdm1d out/fig13_fdm1d --out fig

Prints, per run, how many of its output times have a 1D profile to compare with.

Solid lines with markers: the lattice's shell means u_r (radial.csv, shells binned by undeformed centroid
radius) at the run's output times (the paper's times). Dashed: fdm1d's nodal u_r at the same times.
Dotted (when the benchmark wrote it): the same lattice without fracture, up to the first output time:
the lattice's own error against 1D before fracture. Dash-dot (when the benchmark wrote it): the same
case with the paper's Eq. 16 borehole node instead of the flux boundary (errata E15, E16), its u_r at
the first output time and its borehole pressure with its first break (docs/borehole_fracture.md).
"""
import csv
import os

import numpy as np

import hmplot
from hmplot import plt


def runs_to_draw(data, fdm1d=None):
    """[(label, run folder, 1D folder, twin folder, Eq. 16 node folder)]; None where there is none."""
    index = os.path.join(data, "runs.csv")
    if os.path.exists(index):
        with open(index, newline="") as f:
            rows = [r for r in csv.DictReader(f) if r["figure"] == "1"]
        rows.sort(key=lambda r: float(r["b"]))

        def folder(r, key):
            return os.path.join(data, r[key]) if r.get(key) else None

        return [(r["run"], os.path.join(data, r["run"]), folder(r, "fdm1d"), folder(r, "flux_twin"),
                 folder(r, "eq16_node")) for r in rows]
    by_b = hmplot.fdm1d_folders(fdm1d)
    return [(label, folder, by_b.get(hmplot.run_physics(folder, "b")), None, None)
            for label, folder in hmplot.runs_to_draw(data)]


def existing(folder, name):
    """folder if it holds the file name (a run that failed or was not made has none), else None."""
    return folder if folder and os.path.exists(os.path.join(folder, name)) else None


def check_fdm1d(args):
    """Why these arguments cannot be drawn (no runs in --data, a --fdm1d that is not 1D), or None."""
    problem = hmplot.runs_problem(args.data)
    if problem or not args.fdm1d:
        return problem
    if os.path.exists(os.path.join(args.data, "runs.csv")):
        return f"--fdm1d = {args.fdm1d}: allowed only with run folders ({args.data}/runs.csv names its 1D runs)"
    if not os.path.isdir(args.fdm1d) or not hmplot.fdm1d_folders(args.fdm1d):
        return (f"--fdm1d = {args.fdm1d}: allowed: a folder `hmlattice fdm1d` wrote or a folder of such folders "
                "(no profiles.csv there)")
    return None


def main():
    args = hmplot.arguments(__doc__.splitlines()[0], lambda parser: parser.add_argument(
        "--fdm1d", help="with run folders: an `hmlattice fdm1d` folder at the runs' output times, or a folder of them "
                        "(matched by b)"),
        check_fdm1d)
    runs = runs_to_draw(args.data, args.fdm1d)
    fig, axes = plt.subplots(2, len(runs), figsize=(5.2 * len(runs), 7.4), squeeze=False)
    for col, (label, folder, folder_1d, folder_twin, folder_eq16) in enumerate(runs):
        b = hmplot.run_physics(folder, "b")
        title = f"b = {b:g}" if b is not None else label
        bd = hmplot.read_csv(os.path.join(folder, "breakdown.csv"))
        t_first, p_first = bd["t_first_break"][0], bd["p_h_first_break"][0]
        times = [t for t in hmplot.group_by(hmplot.read_csv(os.path.join(folder, "radial.csv")), "t") if t > 0.0]

        # Top: u_r(r) at the output times.
        ax = axes[0][col]
        n_times, n_compared = hmplot.draw_displacement_vs_1d(ax, folder, folder_1d, t_first)
        print(f"fig13: {title}: {n_times} output times, {n_compared} with a 1D profile")
        twin = existing(folder_twin, "radial.csv")
        if twin:
            tr = hmplot.group_by(hmplot.read_csv(os.path.join(twin, "radial.csv")), "t")
            t_tw = max(tr)
            ax.plot(tr[t_tw]["r_mean"], tr[t_tw]["u_r"], ":", color="C1", lw=1.4,
                    label=f"2D, no fracture, t* = {t_tw:.3g}")
        eq16 = existing(folder_eq16, "radial.csv")
        if eq16:
            er = hmplot.group_by(hmplot.read_csv(os.path.join(eq16, "radial.csv")), "t")
            t_e = min(t for t in er if t > 0.0)
            t_e_first = hmplot.read_csv(os.path.join(eq16, "breakdown.csv"))["t_first_break"][0]
            state = "unbroken" if not (t_e >= t_e_first) else "fractured"
            ax.plot(er[t_e]["r_mean"], er[t_e]["u_r"], "-.", color="C2", lw=1.4,
                    label=f"2D, Eq. 16 borehole node, t* = {t_e:.3g} ({state})")
        ax.set_title(hmplot.run_title(folder, label) + "\n$u_r$: lattice (solid), 1D without fracture (dashed)",
                     fontsize=8)
        ax.legend(loc="best", fontsize=7)

        # Bottom: p_h(t), 2D and 1D, first break marked.
        ax = axes[1][col]
        s = hmplot.read_csv(os.path.join(folder, "series.csv"))
        keep = s["t"] > 0.0
        ax.plot(s["t"][keep], s["p_h"][keep], "-", color="C0", label="2D lattice (fracture)")
        if folder_1d and os.path.exists(os.path.join(folder_1d, "borehole.csv")):
            h = hmplot.read_csv(os.path.join(folder_1d, "borehole.csv"))
            keep1 = h["t"] > 0.0
            ax.plot(h["t"][keep1], h["p_h"][keep1], "--", color="k", lw=1.2, label="1D (fdm1d), no fracture")
        if twin:
            st = hmplot.read_csv(os.path.join(twin, "series.csv"))
            kt = st["t"] > 0.0
            ax.plot(st["t"][kt], st["p_h"][kt], ":", color="C1", lw=1.4,
                    label="2D, no fracture")
        if eq16:
            se = hmplot.read_csv(os.path.join(eq16, "series.csv"))
            ke = se["t"] > 0.0
            ax.plot(se["t"][ke], se["p_h"][ke], "-.", color="C2", lw=1.2, label="2D, Eq. 16 borehole node (fracture)")
            be = hmplot.read_csv(os.path.join(eq16, "breakdown.csv"))
            if np.isfinite(be["t_first_break"][0]):
                ax.plot(be["t_first_break"][:1], be["p_h_first_break"][:1], "s", color="C2", ms=6, mfc="none",
                        label=f"Eq. 16 node: first break t* = {be['t_first_break'][0]:.3g}")
        if np.isfinite(t_first):
            ax.axvline(t_first, color="C3", lw=0.8, ls=":")
            ax.plot([t_first], [p_first], "o", color="C3", ms=6, mfc="none",
                    label=f"first break: t* = {t_first:.3g}, p_h* = {p_first:.3g}")
        for t in times:
            ax.axvline(t, color="0.6", lw=0.6, ls="-", zorder=0)
        ax.set_xscale("log")
        ax.set_xlabel("$t^*$ (grey: output times)")
        ax.set_ylabel("borehole pressure $p_h/E$")
        ax.set_title(f"{title}: borehole pressure", fontsize=9)
        ax.legend(loc="upper left", fontsize=7)
    fig.suptitle("Fig. 13 of Ulven & Sun (2017)\neach column's setting from its config.toml", fontsize=9)
    footer = hmplot.provenance_footer(fig, [run[1] for run in runs])
    fig.set_layout_engine("tight", rect=(0, footer + 0.01, 1, 1))  # room for the footer
    hmplot.save(fig, args.out, "fig13_displacement_vs_1d")


if __name__ == "__main__":
    main()
