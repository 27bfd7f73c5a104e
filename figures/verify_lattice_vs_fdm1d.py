"""Verification figure: the 2D lattice against the radial 1D model before fracture (the dashed curves
of the paper's Figs. 13 and 15), one row per Biot coefficient b.

Reads (written by the benchmarks lattice2d.vs_fdm1d_quick / lattice2d.vs_fdm1d):
  ph_history.csv   b, N, t, p_h (lattice), p_h_1d (fdm1d at the lattice's nu), p_h_1d_nu025 (fdm1d, nu = 0.25)
  profiles_2d.csv  b, N, t, r_mean, u_r, u_r_1d, p, p_1d, u_rel, p_rel (lattice shells, 1D shell means)
  profiles_1d.csv  b, t, r, u_r, p, u_r_nu025, p_nu025 (fdm1d nodes)
  window.csv       t_window (start of the p_h comparison window), t_early (the early time reported)
Columns: A p_h(t), B p_h / p_h,1D - 1 (the comparison window and the +-5% band shaded), C u_r(r) and
D p(r) at the compared times: fdm1d lines (nu = 0.25 dotted), lattice markers (filled N = 1e4 or the
quick tier's N, open the refined N).
"""
import os

import matplotlib.pyplot as plt
import numpy as np

import hmplot

args = hmplot.arguments(__doc__)
ph = hmplot.group_by(hmplot.read_csv(os.path.join(args.data, "ph_history.csv")), "b")
p2 = hmplot.group_by(hmplot.read_csv(os.path.join(args.data, "profiles_2d.csv")), "b")
p1 = hmplot.group_by(hmplot.read_csv(os.path.join(args.data, "profiles_1d.csv")), "b")
t_window = float(hmplot.read_csv(os.path.join(args.data, "window.csv"))["t_window"][0])

bs = list(ph.keys())
fig, axes = plt.subplots(len(bs), 4, figsize=(14, 3.1 * len(bs)), squeeze=False)
colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
for row, b in zip(axes, bs):
    h = hmplot.group_by(ph[b], "N")
    n_values = sorted(h.keys())
    ax = row[0]
    first = h[n_values[0]]
    ax.plot(first["t"], first["p_h_1d"], "k-", label="fdm1d (lattice ν)")
    ax.plot(first["t"], first["p_h_1d_nu025"], "k:", lw=1.0, label="fdm1d (ν = 0.25)")
    for k, n in enumerate(n_values):
        d = h[n]
        ax.plot(d["t"], d["p_h"], "o" if k == 0 else "s", ms=3, mfc="C0" if k == 0 else "none", mec="C0" if k == 0 else "C3",
                ls="none", label=f"lattice N = {n:.0f}")
    ax.set(xscale="log", yscale="log", xlabel="$t^*$", ylabel="$p_h/E$", title=f"b = {b:g}: borehole pressure")
    ax.legend(loc="upper left")

    ax = row[1]
    for k, n in enumerate(n_values):
        d = h[n]
        ax.plot(d["t"], d["p_h"] / d["p_h_1d"] - 1.0, "o-" if k == 0 else "s-", ms=3, lw=0.8,
                color="C0" if k == 0 else "C3", mfc="C0" if k == 0 else "none", label=f"N = {n:.0f}")
    ax.axhspan(-0.05, 0.05, color="0.85", zorder=0, label="±5%")
    ax.axvspan(t_window, first["t"].max(), color="C2", alpha=0.08, zorder=0, label=f"window t* ≥ {t_window:g}")
    ax.set(xscale="log", xlabel="$t^*$", ylabel="p_h / p_h,1D − 1", title=f"b = {b:g}: p_h relative to fdm1d")
    ax.set_yscale("symlog", linthresh=0.1, linscale=3.0)
    ax.set_yticks([-0.1, -0.05, 0.0, 0.05, 0.1, 1.0])
    ax.set_yticklabels(["−10%", "−5%", "0", "5%", "10%", "100%"])
    ax.legend(loc="upper right")

    one_d = hmplot.group_by(p1[b], "t")
    two_d = hmplot.group_by(p2[b], "t")
    for j, (t, d1) in enumerate(one_d.items()):
        c = colours[j % len(colours)]
        row[2].plot(d1["r"], d1["u_r"], "-", color=c)
        row[2].plot(d1["r"], d1["u_r_nu025"], ":", color=c, lw=1.0)
        row[3].plot(d1["r"], d1["p"], "-", color=c, label=f"t* = {t:g}")
        row[3].plot(d1["r"], d1["p_nu025"], ":", color=c, lw=1.0)
        if t in two_d:
            by_n = hmplot.group_by(two_d[t], "N")
            for k, n in enumerate(sorted(by_n.keys())):
                d2 = by_n[n]
                style = dict(ls="none", ms=4, marker="o" if k == 0 else "s", mec=c, mfc=c if k == 0 else "none")
                row[2].plot(d2["r_mean"], d2["u_r"], **style)
                row[3].plot(d2["r_mean"], d2["p"], **style)
    row[2].set(xlabel="$r/R$", ylabel="$u_r/R$", title=f"b = {b:g}: shell-averaged u_r")
    row[3].set(xlabel="$r/R$", ylabel="$p/E$", title=f"b = {b:g}: shell-averaged p")
    # Times in the p panel, line styles in the u_r panel; headroom so the legends clear the curves.
    row[2].plot([], [], "k-", label="fdm1d (lattice ν)")
    row[2].plot([], [], "k:", lw=1.0, label="fdm1d, ν = 0.25")
    row[2].plot([], [], "ko", ms=4, ls="none", label=f"lattice N = {n_values[0]:.0f}")
    if len(n_values) > 1:
        row[2].plot([], [], "ks", ms=4, mfc="none", ls="none", label=f"lattice N = {n_values[1]:.0f}")
    row[2].legend(loc="upper right")
    row[3].legend(loc="upper right")
    for ax in row[2:]:
        lo, hi = ax.get_ylim()
        ax.set_ylim(lo, hi + 0.45 * (hi - lo))
    row[3].axhline(0.0, color="0.5", lw=0.6)
hmplot.save(fig, args.out, "verify_lattice_vs_fdm1d", sources=[args.data])
