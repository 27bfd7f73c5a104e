"""Fig. 18 of Ulven & Sun (2017): the borehole breakdown pressure (p_h when the first beam breaks)
against the injection rate Q, one curve per Biot coefficient b.

Reads the CSV `hmlattice sweep collect` writes for a sweep over physics.Q and physics.b (and any
other keys, e.g. lattice.seed: their runs are drawn as points, their mean as the curve):

    /usr/bin/python3 figures/fig18_breakdown_pressure.py --data out/sweeps/sweep_fig18_quick --out fig

where --data holds results.csv (the Snakemake workflow's `fig18` target writes it and runs this).
A combination whose run is not complete, or that did not break a beam by t_end, is left out and
counted in the printed line. The dotted grey line is the dimensionless tensile strength T_u/E of the
first run's config.toml (the paper compares the breakdown pressure with it). If --data also holds
breakdown_limits.csv (`hmlattice analytic breakdown --b LIST`, which the workflow writes), each b's
closed-form limits of the unfractured 1D model are drawn in its colour: the slow (drained steady state)
limit dashed and the fast (Q -> infinity) limit dash-dotted, both from q_min on, and q_min as a tick
on the Q axis (below it the unfractured 1D wall never fails).

The verification benchmarks lattice2d.fig18_quick and lattice2d.fig18 write another kind of --data
(`hmlattice verify`, their data folder; recognised by its lattice.csv):

    /usr/bin/python3 figures/fig18_breakdown_pressure.py --data verify/data/fig18 --out fig

lattice.csv (one row per lattice run: each seed a small marker, the mean over the seeds of one
resolution a larger one joined by a line, one marker shape per N; the runs with the 1D model's
flux-boundary borehole node as crosses), fdm1d.csv (the grid-converged 1D model: a solid line),
fdm1d_lattice_spacing.csv (the 1D model on a grid of the lattice's mean beam length: a thin dotted
line per N) and breakdown_limits.csv (the limits as above, T_u/E from its tensile_strength column).
"""
import csv
import math
import os
from collections import defaultdict

import hmplot
from hmplot import plt


def read_rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def data_problem(args):
    if os.path.isfile(os.path.join(args.data, "results.csv")) or os.path.isfile(os.path.join(args.data, "lattice.csv")):
        return None
    return (f"--data = '{args.data}' has no results.csv (hmlattice sweep collect) and no lattice.csv "
            "(hmlattice verify, lattice2d.fig18)")


def draw_limits(ax, limits, b, color, q_max):
    """b's slow and fast limits from q_min on, and q_min as a tick on the Q axis."""
    q_min = float(limits[b]["q_min"])
    for column, style in (("p_b_slow", "--"), ("p_b_fast", "-.")):
        ax.hlines(float(limits[b][column]), q_min, q_max, colors=color, linestyles=style, linewidth=0.9)
    ax.axvline(q_min, ymax=0.05, color=color, linewidth=1.5)  # below it the 1D wall never fails


def finish(ax, fig, args, limits, tensile, title, folders=(), legend_outside=False):
    if limits:
        ax.plot([], [], "k--", linewidth=0.9, label="1D slow limit")
        ax.plot([], [], "k-.", linewidth=0.9, label="1D fast limit")
    if tensile:
        ax.axhline(tensile, color="0.4", linestyle=":", linewidth=1.0, label="$T_u/E$")
    ax.set_xscale("log")
    ax.set_xlabel("injection rate $Q$")
    ax.set_ylabel("breakdown pressure $p_h/E$")
    ax.set_title(title, fontsize=8)
    if folders:
        footer = hmplot.provenance_footer(fig, folders)
        fig.set_layout_engine("tight", rect=(0, footer + 0.01, 1, 1))  # room for the footer
    if legend_outside:  # the benchmark's three models fill the axes
        ax.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0.0)
    else:
        ax.legend()
    hmplot.save(fig, args.out, "fig18_breakdown_pressure")


def benchmark_figure(args):
    """The three models of the verification benchmark (lattice per resolution, 1D, limits)."""
    lattice = read_rows(os.path.join(args.data, "lattice.csv"))
    oned = read_rows(os.path.join(args.data, "fdm1d.csv"))
    spacing = read_rows(os.path.join(args.data, "fdm1d_lattice_spacing.csv"))
    limits = {float(r["b"]): r for r in read_rows(os.path.join(args.data, "breakdown_limits.csv"))}
    fig, ax = plt.subplots(figsize=(8.0, 4.4))
    q_max = 2 * max(float(r["Q"]) for r in lattice + oned)
    resolutions = sorted({int(float(r["N"])) for r in lattice})
    shapes = dict(zip(resolutions, "osD^v"))
    colors = {}
    for b in sorted(limits):
        curve = sorted((float(r["Q"]), float(r["p_b"])) for r in oned if float(r["b"]) == b and r["failed"] == "1")
        line, = ax.plot([q for q, _ in curve], [p for _, p in curve], "-", label=f"b = {b:g}: 1D (converged)")
        colors[b] = line.get_color()
        for n in resolutions:
            coarse = sorted((float(r["Q"]), float(r["p_b"])) for r in spacing
                            if float(r["b"]) == b and int(float(r["N"])) == n and r["failed"] == "1")
            ax.plot([q for q, _ in coarse], [p for _, p in coarse], ":", color=colors[b], linewidth=0.8)
            runs = defaultdict(list)
            for r in lattice:
                if float(r["b"]) == b and int(float(r["N"])) == n and r["flux_node"] == "0" and r["broke"] == "1":
                    runs[float(r["Q"])].append(float(r["p_h_first_break"]))
            qs = sorted(runs)
            for q in qs:
                ax.plot([q] * len(runs[q]), runs[q], shapes[n], color=colors[b], markersize=2.5, alpha=0.5)
            ax.plot(qs, [sum(runs[q]) / len(runs[q]) for q in qs], shapes[n] + "-", color=colors[b], linewidth=0.7,
                    markersize=5, markerfacecolor="none")
        flux = [(float(r["Q"]), float(r["p_h_first_break"])) for r in lattice
                if float(r["b"]) == b and r["flux_node"] == "1" and r["broke"] == "1"]
        ax.plot([q for q, _ in flux], [p for _, p in flux], "x", color=colors[b], markersize=6)
        draw_limits(ax, limits, b, colors[b], q_max)
    for n in resolutions:
        ax.plot([], [], shapes[n] + "-", color="k", linewidth=0.7, markerfacecolor="none",
                label=f"lattice N = {n} (mean, seeds)")
    ax.plot([], [], "k:", linewidth=0.8, label="1D at the lattice spacing")
    if any(r["flux_node"] == "1" for r in lattice):
        ax.plot([], [], "kx", label="lattice, 1D's flux node")
    tensile = float(next(iter(limits.values()))["tensile_strength"]) if limits else None
    finish(ax, fig, args, limits, tensile, "Fig. 18 of Ulven & Sun (2017): breakdown pressure against $Q$; lattice, "
           "1D model and its limits", legend_outside=True)
    print(f"fig18: {len(lattice)} lattice runs, {len(oned)} 1D rates -> "
          f"{os.path.join(args.out, 'fig18_breakdown_pressure')}.png")


def main():
    args = hmplot.arguments(__doc__.splitlines()[0], check=data_problem)
    if not os.path.isfile(os.path.join(args.data, "results.csv")):
        benchmark_figure(args)
        return
    rows = read_rows(os.path.join(args.data, "results.csv"))
    for column in ("physics.Q", "physics.b", "status", "p_h_first_break"):
        if rows and column not in rows[0]:
            raise SystemExit(f"{args.data}/results.csv: no column {column} (a sweep over physics.Q and physics.b)")
    points = defaultdict(lambda: defaultdict(list))  # b -> Q -> breakdown pressures
    skipped = 0
    for r in rows:
        p = float(r["p_h_first_break"]) if r["status"] == "complete" and r["p_h_first_break"] else math.nan
        if math.isnan(p):
            skipped += 1
            continue
        points[float(r["physics.b"])][float(r["physics.Q"])].append(p)

    limits = {}
    limits_file = os.path.join(args.data, "breakdown_limits.csv")
    if os.path.isfile(limits_file):
        limits = {float(r["b"]): r for r in read_rows(limits_file)}

    fig, ax = plt.subplots(figsize=(4.5, 3.4))
    all_q = sorted({q for b in points for q in points[b]})
    for b in sorted(points):
        qs = sorted(points[b])
        line, = ax.plot(qs, [sum(points[b][q]) / len(points[b][q]) for q in qs], marker="o", label=f"b = {b:g}")
        for q in qs:
            ax.plot([q] * len(points[b][q]), points[b][q], ".", color=line.get_color(), alpha=0.4)
        if b in limits:
            draw_limits(ax, limits, b, line.get_color(), all_q[-1] * 2)
    complete = [r for r in rows if r["status"] == "complete"]
    tensile = hmplot.run_physics(os.path.join(args.data, "runs", complete[0]["name"]), "tensile_strength") if complete else None
    # The setting the sweep holds fixed, from its first complete run (Q and b are the axes and curves).
    folders = [os.path.join(args.data, "runs", r["name"]) for r in complete]
    config = hmplot.run_config(folders[0]) if folders else {}
    iota, n = config.get("physics", {}).get("iota"), config.get("lattice", {}).get("n_particles")
    fixed = ", ".join(part for part in (f"$\\iota = {iota:g}$" if iota is not None else "",
                                        f"$N = {n}$" if n is not None else "") if part)
    finish(ax, fig, args, limits, tensile, "Fig. 18 of Ulven & Sun (2017)" + (f"; {fixed}" if fixed else ""),
           folders)
    print(f"fig18: {len(rows) - skipped} of {len(rows)} combinations drawn ({skipped} incomplete or without a break)"
          f" -> {os.path.join(args.out, 'fig18_breakdown_pressure')}.png")


if __name__ == "__main__":
    main()
