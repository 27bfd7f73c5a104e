"""Fig. 10 of Ulven & Sun (2017): pressure and displacement of the radial 1D model.

Reads a run folder written by `hmlattice fdm1d` (profiles.csv, probes.csv, steady_state.csv):
    build/hmlattice fdm1d cases/fig10_fdm1d_b0.5.toml --out out/fig10
    /usr/bin/python3 figures/fig10_fdm1d_pressure_displacement.py --data out/fig10 --out out/fig10
A: p(r) at the output times, B: u_r(r), both with the steady state of Appendix B dashed;
C: p(t) at the probes; D: the start of C, where the pressure first goes negative (Mandel-Cryer).
"""
import os

import matplotlib.pyplot as plt
import numpy as np

import hmplot

args = hmplot.arguments(__doc__)
profiles = hmplot.group_by(hmplot.read_csv(os.path.join(args.data, "profiles.csv")), "t")
probes = hmplot.read_csv(os.path.join(args.data, "probes.csv"))
steady = hmplot.read_csv(os.path.join(args.data, "steady_state.csv"))

fig, ax = plt.subplots(2, 2, figsize=(8, 6.4))
for t, d in profiles.items():
    ax[0, 0].plot(d["r"], d["p"], label=f"t* = {t:g}")
    ax[0, 1].plot(d["r"], d["u_r"], label=f"t* = {t:g}")
ax[0, 0].plot(steady["r"], steady["p"], "k--", label="steady, Eq. B3")
ax[0, 1].plot(steady["r"], steady["u_r"], "k--", label="steady, Eq. B6 (corrected)")
ax[0, 0].set(xlabel="$r/R$", ylabel="$p/E$", title="A  pressure")
ax[0, 1].set(xlabel="$r/R$", ylabel="$u_r/R$", title="B  radial displacement")
ax[0, 0].legend()

t = probes["t"]
columns = [c for c in probes if c.startswith("p_r")]
t_zoom = 0.05 * t.max()
zoom = t <= t_zoom
for c in columns:
    label = "r* = " + c[3:]
    ax[1, 0].plot(t, probes[c], label=label)
    ax[1, 1].plot(t[zoom], probes[c][zoom], label=label)
ax[1, 0].set(xlabel="$t^*$", ylabel="$p/E$", title="C  pressure at the probes")
ax[1, 1].set(xlabel="$t^*$", ylabel="$p/E$", title="D  start of C: transient negative pressure")
ax[1, 1].axhline(0.0, color="k", lw=0.6)
lo = min(np.min(probes[c][zoom]) for c in columns)
ax[1, 1].set_ylim(1.5 * lo if lo < 0 else -1e-6, -2.0 * lo if lo < 0 else 1e-6)
ax[1, 0].legend()
hmplot.save(fig, args.out, "fig10_fdm1d_pressure_displacement", sources=[args.data])
