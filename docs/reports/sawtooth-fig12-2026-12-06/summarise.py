"""summary.csv and table.md of the saw-tooth Fig. 12 study from its run folders (complete or not).
Usage: /usr/bin/python3 summarise.py RUNS OUT [LABEL]   (LABEL names the setting in table.md)
Rows of an earlier OUT/summary.csv whose (N, seed) has no run folder in RUNS are kept: a study's runs
may be made in several sessions, in different folders."""
import os
import sys

import pandas as pd

runs, out = sys.argv[1], sys.argv[2]
os.makedirs(out, exist_ok=True)
label = sys.argv[3] if len(sys.argv) > 3 else "saw-tooth Fig. 12 b = 0.2, G_f/(ER) = 2.34e-9"
rows = []
for name in sorted(os.listdir(runs)):
    folder = os.path.join(runs, name)
    summary_path = os.path.join(folder, "fracture_summary.csv")
    if not os.path.exists(summary_path):
        continue
    summary = pd.read_csv(summary_path)
    series = pd.read_csv(os.path.join(folder, "series.csv"))
    teeth = pd.read_csv(os.path.join(folder, "teeth.csv"))
    complete = not os.path.exists(os.path.join(folder, "checkpoint.bin"))
    n = int(name.split("_seed=")[0].split("=")[1])
    seed = int(name.split("_seed=")[1])
    for _, s in summary[summary.t > 0].iterrows():
        at = series[series.t <= s.t + 1e-12]
        rows.append({"N": n, "seed": seed, "t": s.t, "complete": complete,
                     "p_h": at.p_h.iloc[-1], "teeth": int((teeth.time <= s.t + 1e-12).sum()),
                     "dissipated": teeth[teeth.time <= s.t + 1e-12].energy.sum(),
                     "broken": int(s.n_broken), "arms_3_beams": int(s.n_arms), "arms_gap_0.03": int(s.n_arms_fixed_gap),
                     "radial": int(s.n_radial), "reaching_r1": int(s.n_radial_reaching_outer),
                     "max_radial_extent": s.max_radial_extent, "secondary": int(s.n_secondary),
                     "secondary_sizable": int(s.n_secondary_sizable)})
table = pd.DataFrame(rows)
earlier_path = os.path.join(out, "summary.csv")
if os.path.exists(earlier_path):
    earlier = pd.read_csv(earlier_path)
    here = set(zip(table.N, table.seed)) if len(table) else set()
    table = pd.concat([table, earlier[[(n, s) not in here for n, s in zip(earlier.N, earlier.seed)]]])
table = table.sort_values(["t", "N", "seed"])
table.to_csv(os.path.join(out, "summary.csv"), index=False, float_format="%.6g")
means = table.groupby(["t", "N"]).mean(numeric_only=True).drop(columns=["seed"])
spread = table.groupby(["t", "N"]).std(numeric_only=True)  # the seeds' standard deviation (NaN for one)
counts = table.groupby(["t", "N"]).size()
with open(os.path.join(out, "table.md"), "w") as f:
    f.write(f"Means over the seeds that reached each time, ± their standard deviation ({label}).\n\n")
    f.write("| t* | N | seeds | p_h | teeth | dissipated | broken | arms (3 beams) | arms (gap 0.03 R) | radial | at r = 1 "
            "| max radial extent | secondaries | sizable secondaries |\n|" + "---|" * 14 + "\n")
    for (t, n), m in means.iterrows():
        sd = spread.loc[(t, n)]
        pm = (lambda v, fmt: "" if pd.isna(v) else f" ± {v:{fmt}}")
        f.write(f"| {t:g} | {n} | {counts[(t, n)]} | {m.p_h:.3e}{pm(sd.p_h, '.1e')} | {m.teeth:.0f} | "
                f"{m.dissipated:.3e}{pm(sd.dissipated, '.1e')} | {m.broken:.0f}{pm(sd.broken, '.0f')} | "
                f"{m.arms_3_beams:.1f} | {m['arms_gap_0.03']:.1f} | {m.radial:.1f} | {m.reaching_r1:.1f} | "
                f"{m.max_radial_extent:.3f} | {m.secondary:.0f} | {m.secondary_sizable:.1f} |\n")
print(f"wrote {out}/summary.csv and table.md ({len(table)} rows)")
