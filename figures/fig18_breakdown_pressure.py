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
"""
import csv
import math
import os
from collections import defaultdict

import hmplot
from hmplot import plt


def main():
    args = hmplot.arguments(__doc__.splitlines()[0], check=lambda a: None if os.path.isfile(
        os.path.join(a.data, "results.csv")) else f"--data = '{a.data}' has no results.csv (hmlattice sweep collect)")
    with open(os.path.join(args.data, "results.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
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
        with open(limits_file, newline="") as f:
            limits = {float(r["b"]): r for r in csv.DictReader(f)}

    fig, ax = plt.subplots(figsize=(4.5, 3.4))
    all_q = sorted({q for b in points for q in points[b]})
    for b in sorted(points):
        qs = sorted(points[b])
        line, = ax.plot(qs, [sum(points[b][q]) / len(points[b][q]) for q in qs], marker="o", label=f"b = {b:g}")
        for q in qs:
            ax.plot([q] * len(points[b][q]), points[b][q], ".", color=line.get_color(), alpha=0.4)
        if b in limits:
            q_min = float(limits[b]["q_min"])
            for column, style in (("p_b_slow", "--"), ("p_b_fast", "-.")):
                ax.hlines(float(limits[b][column]), q_min, all_q[-1] * 2, colors=line.get_color(), linestyles=style,
                          linewidth=0.9)
            ax.axvline(q_min, ymax=0.05, color=line.get_color(), linewidth=1.5)  # below it the 1D wall never fails
    if limits:
        ax.plot([], [], "k--", linewidth=0.9, label="1D slow limit")
        ax.plot([], [], "k-.", linewidth=0.9, label="1D fast limit")
    complete = [r for r in rows if r["status"] == "complete"]
    tensile = hmplot.run_physics(os.path.join(args.data, "runs", complete[0]["name"]), "tensile_strength") if complete else None
    if tensile:
        ax.axhline(tensile, color="0.4", linestyle=":", linewidth=1.0, label="$T_u/E$")
    ax.set_xscale("log")
    ax.set_xlabel("injection rate $Q$")
    ax.set_ylabel("breakdown pressure $p_h/E$")
    ax.legend()
    hmplot.save(fig, args.out, "fig18_breakdown_pressure")
    print(f"fig18: {len(rows) - skipped} of {len(rows)} combinations drawn ({skipped} incomplete or without a break)"
          f" -> {os.path.join(args.out, 'fig18_breakdown_pressure')}.png")


if __name__ == "__main__":
    main()
