"""Fig. 8 of Ulven & Sun (2017): convergence of the coupling passes for different Psi.

Reads passes.csv (psi, pass, p_shell) written by the paper-tier benchmark lattice2d.psi_study:
the area-weighted mean pressure in the shell Gamma, 0.02 < r* < 0.03 (Fig. 6), after every pass of
one implicit step dt* = 3e-4 from rest in the Fig. 7 setting, for each Psi (Psi = 0: the drained
split, Eqs. 17-20).
    build/hmlattice verify --tier paper --filter psi_study --out out/verify_fig08
    /usr/bin/python3 figures/fig08_psi_study.py --data out/verify_fig08/data/psi_study --out out/fig08
Left: p_shell against the pass number, one curve per Psi (the paper's figure). Right: its distance
from the same Psi's last pass, |p_k - p_last| / |p_last|, on a log axis, to show the rate.
Writes fig08_psi_study.png and .pdf.
"""
import os

import matplotlib.pyplot as plt
import numpy as np

import hmplot

args = hmplot.arguments(__doc__)
runs = hmplot.group_by(hmplot.read_csv(os.path.join(args.data, "passes.csv")), "psi")

fig, (ax, rate) = plt.subplots(1, 2, figsize=(9, 3.8))
for k, (psi, d) in enumerate(sorted(runs.items())):
    order = np.argsort(d["pass"])
    n, p = d["pass"][order], d["p_shell"][order]
    label = f"Ψ = {psi:g}" + (" (drained)" if psi == 0.0 else "") + f", {len(n)} passes"
    colour = f"C{k}"
    ax.plot(n, p, "-o", color=colour, markersize=3, label=label)
    distance = np.abs(p[:-1] - p[-1]) / abs(p[-1])
    shown = distance > 0.0  # exact repeats of the last value cannot go on a log axis
    rate.semilogy(n[:-1][shown], distance[shown], "-o", color=colour, markersize=3, label=label)
ax.set(xlabel="coupling pass", ylabel="$p^*$ in shell Γ (area-weighted mean)",
       title="shell pressure after each pass")
ax.ticklabel_format(axis="y", style="sci", scilimits=(-2, 2))
rate.set(xlabel="coupling pass", ylabel="$|p_k - p_{last}|\\,/\\,|p_{last}|$",
         title="distance from the last pass")
ax.legend()
fig.suptitle("Fig. 8 — point injection (Q = 0.1, b = 0.5): one step $\\Delta t^*$ = 3e-4 from rest, "
             "shell Γ: 0.02 < $r^*$ < 0.03", fontsize=10)
hmplot.save(fig, args.out, "fig08_psi_study")
