"""summary.csv (one row per run) and table.md (means and standard deviations over the seeds) of run.sh's runs."""
import glob
import os
import re
import sys

import pandas as pd

runs, here = sys.argv[1], sys.argv[2]
rows = []
for folder in sorted(glob.glob(os.path.join(runs, "*"))):
    summary = os.path.join(folder, "fracture_summary.csv")
    m = re.fullmatch(r"(paper|candidate)_n(\d+)_s(\d)_dt([\d.e-]+)_(pass|conv|spring)", os.path.basename(folder))
    if not m or not os.path.exists(summary):
        continue
    last = pd.read_csv(summary).iloc[-1]
    breakdown = pd.read_csv(os.path.join(folder, "breakdown.csv")).iloc[0]
    rows.append(dict(setting=m[1], N=int(m[2]), seed=int(m[3]), dt_max=float(m[4]), check=m[5], t=last.t,
                     broken=int(last.n_broken), arms=int(last.n_arms), arms_gap=int(last.n_arms_fixed_gap),
                     at_r1=int(last.n_radial_reaching_outer), t_first_break=breakdown.t_first_break,
                     p_h_first_break=breakdown.p_h_first_break, p_h_peak=breakdown.p_h_peak))
df = pd.DataFrame(rows).sort_values(["setting", "N", "check", "dt_max", "seed"], ascending=[False, True, False, False, True])
df.to_csv(os.path.join(here, "summary.csv"), index=False)
names = {"pass": "every pass, all at once", "conv": "at convergence, one at a time", "spring": "every pass, borehole spring"}
lines = ["Means over seeds 1-3 ± their standard deviation at t* = 0.0272 (brittle Fig. 12 b = 0.2; run.sh).", "",
         "| setting | N | breaks checked | dt_max | broken | arms (3 beams) | arms (gap 0.03 R) | at r = 1 | first break t* | p_h at first break | peak p_h |",
         "|---|---|---|---|---|---|---|---|---|---|---|"]
order = {"pass": 0, "spring": 1, "conv": 2}
for (setting, n, check, dt), g in sorted(df.groupby(["setting", "N", "check", "dt_max"]),
                                         key=lambda kv: (kv[0][0] != "paper", kv[0][1], order[kv[0][2]], -kv[0][3])):
    sd = lambda c: f" ± {g[c].std():.2g}" if len(g) > 1 else ""
    lines.append(f"| {setting} | {n} | {names[check]} | {dt:g} | {g.broken.mean():.0f}{sd('broken')} | "
                 f"{g.arms.mean():.2f}{sd('arms')} | {g.arms_gap.mean():.2f} | {g.at_r1.mean():.2f} | "
                 f"{g.t_first_break.mean():.3g} | {g.p_h_first_break.mean():.3g} | {g.p_h_peak.mean():.3g} |")
with open(os.path.join(here, "table.md"), "w") as f:
    f.write("\n".join(lines) + "\n")
print(f"wrote {here}/summary.csv and table.md ({len(df)} runs)")
