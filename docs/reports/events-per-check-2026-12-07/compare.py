"""summary.csv and table.md of the events_per_check comparison from its run folders.
Usage: /usr/bin/python3 compare.py OUT HERE  (OUT holds runs_<setting>_epc<k>/n_particles=<N>_seed=<s>/)"""
import os
import re
import sys

import pandas as pd

out, here = sys.argv[1], sys.argv[2]
rows = []
for folder in sorted(os.listdir(out)):
    m = re.fullmatch(r"runs_(.+)_epc(\d+)", folder)
    if not m:
        continue
    setting, k = m.group(1), int(m.group(2))
    for name in sorted(os.listdir(os.path.join(out, folder))):
        run = os.path.join(out, folder, name)
        if not os.path.isdir(run) or not os.path.exists(os.path.join(run, "fracture_summary.csv")):
            continue
        n = int(name.split("_seed=")[0].split("=")[1])
        seed = int(name.split("_seed=")[1])
        with open(run + ".time") as f:
            wall = float(f.read().split()[0])
        with open(run + ".log") as f:
            passes = int(re.search(r"(\d+) coupling iterations", f.read()).group(1))
        summary = pd.read_csv(os.path.join(run, "fracture_summary.csv"))
        series = pd.read_csv(os.path.join(run, "series.csv"))
        teeth = pd.read_csv(os.path.join(run, "teeth.csv"))
        for _, s in summary[summary.t > 0].iterrows():
            upto = teeth[teeth.time <= s.t + 1e-12]
            rows.append({"setting": setting, "N": n, "events_per_check": k, "seed": seed, "t": s.t,
                         "wall_s": wall, "passes": passes,
                         "p_h": series[series.t <= s.t + 1e-12].p_h.iloc[-1], "teeth": len(upto),
                         "dissipated": upto.energy.sum(), "broken": int(s.n_broken),
                         "arms_3_beams": int(s.n_arms), "arms_gap_0.03": int(s.n_arms_fixed_gap),
                         "reaching_r1": int(s.n_radial_reaching_outer), "max_radial_extent": s.max_radial_extent})
table = pd.DataFrame(rows).sort_values(["setting", "N", "t", "events_per_check", "seed"])
table.to_csv(os.path.join(here, "summary.csv"), index=False, float_format="%.6g")
cols = ["p_h", "broken", "dissipated", "arms_3_beams", "arms_gap_0.03", "reaching_r1", "max_radial_extent"]
with open(os.path.join(here, "table.md"), "w") as f:
    f.write("Means over the seeds ± their standard deviation; wall time and passes of the whole run.\n\n")
    f.write("| setting | N | seeds | t* | events/check | wall [s] | passes | " + " | ".join(cols) + " |\n")
    f.write("|" + "---|" * (7 + len(cols)) + "\n")
    for (setting, n, t, k), g in table.groupby(["setting", "N", "t", "events_per_check"]):
        def cell(c):
            return f"{g[c].mean():.4g} ± {g[c].std():.2g}" if len(g) > 1 else f"{g[c].mean():.4g}"
        f.write(f"| {setting} | {n} | {len(g)} | {t:g} | {k} | {g.wall_s.mean():.0f} | {g.passes.mean():.0f} | "
                + " | ".join(cell(c) for c in cols) + " |\n")
print(open(os.path.join(here, "table.md")).read())
