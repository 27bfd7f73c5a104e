"""summary.csv of the cubic-law comparison from its run folders and logs.
Usage: /usr/bin/python3 summarise.py RUNS OUT"""
import os
import re
import sys

import pandas as pd

runs, out = sys.argv[1], sys.argv[2]
rows=[]
for c in ["fig14_b0.2","fig14_b0.8","fig17_b0.2","fig17_b0.8","fig16_b0.2","fig16_b0.8","fig12_b0.2"]:
    for law in ["iota","cubic"]:
        d=os.path.join(runs, f"{c}_{law}")
        if not os.path.exists(f"{d}/fracture_summary.csv"): continue
        s=pd.read_csv(f"{d}/series.csv"); f=pd.read_csv(f"{d}/fracture_summary.csv").iloc[-1]
        fp=pd.read_csv(f"{d}/fracture_pressure.csv").iloc[-1]
        log=open(d + ".log").read()
        secs=float(re.search(r"peak memory \d+ MB \(([\d.]+) s\)",log).group(1))
        passes=int(re.search(r"(\d+) coupling iterations",log).group(1))
        rows.append(dict(case=c,law=law,t_end=s.t.iloc[-1],peak_p_h=s.p_h.max(),t_peak=s.t[s.p_h.idxmax()],final_p_h=s.p_h.iloc[-1],
                         broken=int(f.n_broken),arms=int(f.n_arms),arms_gap=int(f.n_arms_fixed_gap),at_r1=int(f.n_radial_reaching_outer),
                         backflow=fp.borehole_backflow,passes=passes,seconds=secs,ms_per_pass=1000*secs/passes))
t = pd.DataFrame(rows)
print(t.to_string())
os.makedirs(out, exist_ok=True)
t.to_csv(os.path.join(out, "summary.csv"), index=False, float_format="%.4g")
