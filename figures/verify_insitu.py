"""Verification figure: the dry lattice under an in-situ far field.

Reads insitu_wall_hoop.csv (field, psi_deg, sigma_theta_lattice, sigma_theta_annulus: one row per wall
particle and seed; field 0, 1, 2 are S_H - S_h = 0, 1e-4, 2e-4) and insitu_breakdown.csv (S_H, S_h,
seed, p_b_lattice, psi_deg, p_b_annulus, p_b_overread, p_b_hubbert_willis). Draws the wall hoop stress
against the angle from S_H, and the jacketed breakdown pressure against S_H - S_h.
"""
import os

import matplotlib.pyplot as plt
import numpy as np

import hmplot

args = hmplot.arguments(__doc__)
hoop = hmplot.read_csv(os.path.join(args.data, "insitu_wall_hoop.csv"))
breakdown = hmplot.read_csv(os.path.join(args.data, "insitu_breakdown.csv"))

fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4.2))
for k, (field, d) in enumerate(sorted(hmplot.group_by(hoop, "field").items())):
    order = np.argsort(d["psi_deg"])
    colour = f"C{k}"
    left.plot(d["psi_deg"], d["sigma_theta_lattice"], ".", ms=3, color=colour, alpha=0.5)
    left.plot(d["psi_deg"][order], d["sigma_theta_annulus"][order], "-", lw=1.2, color=colour,
              label=f"annulus, (S_H − S_h)/E = {field:.0f}e-4")
left.axhline(2e-4, color="k", ls=":", lw=1, label="T_u")
left.set(xlabel="angle from S_H [deg]", ylabel="wall $\\sigma_\\theta/E$ (at $p_w = 0$)",
         title="wall hoop stress: lattice particles (dots), finite annulus (lines)")
left.legend(fontsize=8)

dS = 1e4 * (breakdown["S_H"] - breakdown["S_h"])
order = np.argsort(dS)
right.plot(dS, breakdown["p_b_lattice"], "o", label="lattice (3 seeds)")
right.plot(dS[order], breakdown["p_b_annulus"][order], "k-", label="finite annulus, jacketed")
right.plot(dS[order], breakdown["p_b_overread"][order], "k--", label="annulus with the wall over-read")
right.plot(dS[order], breakdown["p_b_hubbert_willis"][order], "k:", label="Hubbert–Willis (Kirsch)")
right.set(xlabel="(S_H − S_h)/E × 1e4  (mean stress 2e-4 E)", ylabel="breakdown $p_w/E$", title="jacketed breakdown pressure")
right.legend(fontsize=8)
hmplot.save(fig, args.out, "verify_insitu", sources=[args.data])
