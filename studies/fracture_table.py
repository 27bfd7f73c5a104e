"""Fracture statistics of a sweep, per cell (every swept key but the seeds), as mean and spread over
the seeds: the tables of docs/fracture_study.md.

    hmlattice sweep collect SWEEP/cases --runs SWEEP/runs > SWEEP/results.csv
    /usr/bin/python3 studies/fracture_table.py SWEEP [--csv OUT.csv] > OUT.md

Reads SWEEP/results.csv and, per complete run, SWEEP/runs/<name>/fractures.csv at the run's last
output time. Scores, as the paper's Figs. 12 and 19 are read: radial fractures crossing r = 0.5,
radial fractures reaching r = 1, arms, secondary clusters, first-break time and pressure.
"""
import argparse
import csv
import math
import os
import statistics
import sys
from collections import defaultdict

SEED_KEYS = ("lattice.seed", "fracture.seed")
HALFWAY = 0.5  # "crossing r = 0.5": a fracture that got past the middle of the annulus


def last_snapshot_counts(run_folder):
    """Radial fractures crossing r = 0.5 and reaching r = 1 at the last output time of fractures.csv."""
    with open(os.path.join(run_folder, "fractures.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        return 0, 0
    t_last = max(float(r["t"]) for r in rows)
    radial = [r for r in rows if float(r["t"]) == t_last and r["kind"] == "radial"]
    return (sum(float(r["r_max"]) >= HALFWAY for r in radial), sum(r["reaches_outer"] == "1" for r in radial))


def mean_spread(values):
    """'m ± s' (sample standard deviation over seeds), or 'm' for one value."""
    values = [v for v in values if not math.isnan(v)]
    if not values:
        return "—"
    m = statistics.fmean(values)
    return f"{m:.3g} ± {statistics.stdev(values):.2g}" if len(values) > 1 else f"{m:.3g}"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("sweep", help="folder with results.csv and runs/")
    parser.add_argument("--csv", help="also write one row per run with the scores")
    args = parser.parse_args()
    results = os.path.join(args.sweep, "results.csv")
    if not os.path.isfile(results):
        parser.error(f"{results} does not exist (hmlattice sweep collect)")
    with open(results, newline="") as f:
        runs = list(csv.DictReader(f))
    header = list(runs[0].keys()) if runs else []
    swept = [k for k in header[1:header.index("status")] if k not in SEED_KEYS]

    scores = []
    for r in runs:
        if r["status"] != "complete":
            continue
        crossing, reaching = last_snapshot_counts(os.path.join(args.sweep, "runs", r["name"]))
        scores.append({"name": r["name"], **{k: r[k] for k in swept}, "crossing_r0.5": crossing,
                       "reaching_r1": reaching, "arms": int(r["final_n_arms"]),
                       "secondary": int(r["final_n_secondary"]), "broken": int(r["final_n_broken"]),
                       "t_first_break": float(r["t_first_break"] or "nan"),
                       "p_first_break": float(r["p_h_first_break"] or "nan"), "wall_seconds": int(r["wall_seconds"])})
    if args.csv:
        with open(args.csv, "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=list(scores[0].keys()) if scores else ["name"])
            w.writeheader()
            w.writerows(scores)

    cells = defaultdict(list)
    for s in scores:
        cells[tuple(s[k] for k in swept)].append(s)
    columns = ["crossing_r0.5", "reaching_r1", "arms", "secondary", "broken", "t_first_break", "p_first_break"]
    print("| " + " | ".join(swept + ["seeds"] + columns) + " |")
    print("|" + "---|" * (len(swept) + 1 + len(columns)))
    def numeric_first(cell):  # numbers in numeric order (3000 before 10000), then text
        return tuple((0, float(v), "") if v.replace(".", "", 1).replace("e-", "", 1).isdigit() else (1, 0.0, v) for v in cell)

    for cell in sorted(cells, key=numeric_first):
        group = cells[cell]
        print("| " + " | ".join(list(cell) + [str(len(group))] + [mean_spread([float(g[c]) for g in group]) for c in columns]) + " |")
    incomplete = len(runs) - len(scores)
    if incomplete:
        print(f"\n{incomplete} of {len(runs)} runs not complete (left out).", file=sys.stderr)


if __name__ == "__main__":
    main()
