"""Fig. 11 of Ulven & Sun (2017): effective stresses and Coulomb stress of the radial 1D model.

Reads a run folder written by `hmlattice fdm1d` (profiles.csv, steady_state.csv):
    /usr/bin/python3 figures/fig11_fdm1d_stresses.py --data out/fig10 --out out/fig10
A: sigma_r, B: sigma_theta, C: sigma_z (effective, tension positive), D: sigma_CC of Eq. 11,
at the output times, with the steady state of Appendix B (corrected B7-B9) dashed.
"""
import os

import matplotlib.pyplot as plt

import hmplot

args = hmplot.arguments(__doc__)
profiles = hmplot.group_by(hmplot.read_csv(os.path.join(args.data, "profiles.csv")), "t")
steady = hmplot.read_csv(os.path.join(args.data, "steady_state.csv"))

panels = [("sigma_r", "A  radial stress σ_r*"), ("sigma_theta", "B  tangential stress σ_θ*"),
          ("sigma_z", "C  axial stress σ_z*"), ("coulomb", "D  Coulomb stress σ_CC*")]
fig, axes = plt.subplots(2, 2, figsize=(8, 6.4))
for ax, (column, title) in zip(axes.flat, panels):
    for t, d in profiles.items():
        ax.plot(d["r"], d[column], label=f"t* = {t:g}")
    ax.plot(steady["r"], steady[column], "k--", label="steady, Appendix B")
    ax.axhline(0.0, color="k", lw=0.5)
    ax.set(xlabel="$r/R$", title=title)
axes[0, 0].legend()
hmplot.save(fig, args.out, "fig11_fdm1d_stresses", sources=[args.data])
