"""Fig. 8 of Ulven & Sun (2017): convergence of the coupling passes for different Psi.

Reads passes.csv (psi, pass, p_shell) written by the paper-tier benchmark lattice2d.psi_study:
the area-weighted mean pressure in the shell Gamma, 0.02 < r* < 0.03 (Fig. 6), after every pass of
one implicit step dt* = 3e-4 from rest in the Fig. 7 setting, for each Psi (Psi = 0: the drained
split, Eqs. 17-20).
    build/hmlattice verify --tier paper --filter psi_study --out out/verify_fig08
    /usr/bin/python3 figures/fig08_psi_study.py --data out/verify_fig08/data/psi_study --out out/fig08
Left: p_shell against the pass number, one curve per Psi (the paper's figure; the first 25 passes).
Right: its distance from the same Psi's last pass, |p_k - p_last| / |p_last|, on a log axis, to
show the rate; open markers lie below the last value (an overshoot changes the fill).
Writes fig08_psi_study.png and .pdf.
"""
import os

import matplotlib.pyplot as plt
import numpy as np

import hmplot

args = hmplot.arguments(__doc__)
runs = hmplot.group_by(hmplot.read_csv(os.path.join(args.data, "passes.csv")), "psi")

N_ZOOM = 25  # the left panel shows the first passes, where the splits differ in kind

fig, (ax, rate) = plt.subplots(1, 2, figsize=(9, 3.8))
n_max = 0
for k, (psi, d) in enumerate(sorted(runs.items())):
    order = np.argsort(d["pass"])
    n, p = d["pass"][order], d["p_shell"][order]
    n_max = max(n_max, int(n.max()))
    label = f"Ψ = {psi:g}" + (" (drained)" if psi == 0.0 else "") + f": {len(n)} passes"
    colour = f"C{k}"
    ax.plot(n, p, "-o", color=colour, markersize=3, label=label)
    # Right: distance from the last pass, filled above it and open below it, so an overshoot shows
    # as a change of fill. Exact repeats of the last value cannot go on a log axis.
    distance = (p[:-1] - p[-1]) / abs(p[-1])
    rate.semilogy(n[:-1], np.abs(distance), "-", color=colour, lw=1.0)
    for side, face in ((distance > 0.0, colour), (distance < 0.0, "white")):
        rate.plot(n[:-1][side], np.abs(distance[side]), "o", color=colour, markerfacecolor=face, markersize=3.5)
zoom = n_max > N_ZOOM
ax.set(xlabel="coupling pass", ylabel="$p^*$ in shell Γ (area-weighted mean)")
ax.set_title("shell pressure after each pass" + (f" (first {N_ZOOM})" if zoom else ""),
             pad=12)  # room for the axis' 1e-3 above the frame
if zoom:
    ax.set_xlim(0.5, N_ZOOM + 0.5)
ax.ticklabel_format(axis="y", style="sci", scilimits=(-2, 2))
rate.set(xlabel="coupling pass", ylabel="$|p_k - p_{last}|\\,/\\,|p_{last}|$",
         title="distance from the last pass (open: below it)")
ax.legend()
fig.suptitle("Fig. 8 — point injection (Q = 0.1, b = 0.5): one step $\\Delta t^*$ = 3e-4 from rest, "
             "shell Γ: 0.02 < $r^*$ < 0.03", fontsize=10)
hmplot.save(fig, args.out, "fig08_psi_study", sources=[args.data])
