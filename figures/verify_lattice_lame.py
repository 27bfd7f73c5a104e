"""Verification figure: Lame's thick-walled cylinder on the calibrated lattice.

Reads lattice_lame.csv (columns n_particles, outer_fixed, r_u, u_r, u_r_exact, r_sigma, sigma_theta,
sigma_theta_exact: one row per radial shell; the exact values are averaged over the same particles as
the lattice's). Draws u_r and sigma_theta against r for the free and the fixed outer boundary.
"""
import os

import matplotlib.pyplot as plt

import hmplot

args = hmplot.arguments(__doc__)
data = hmplot.read_csv(os.path.join(args.data, "lattice_lame.csv"))
by_outer = hmplot.group_by(data, "outer_fixed")

fig, axes = plt.subplots(2, 2, figsize=(9, 6.2))
markers = ["o", "s", "^", "D"]
for row, (outer, d) in enumerate(sorted(by_outer.items())):
    label_outer = "fixed" if outer else "free"
    for k, (n, dn) in enumerate(hmplot.group_by(d, "n_particles").items()):
        m = markers[k % len(markers)]
        axes[row][0].plot(dn["r_u"], dn["u_r"], m, ms=4, label=f"lattice N = {n:.0f}")
        axes[row][1].plot(dn["r_sigma"], dn["sigma_theta"], m, ms=4, label=f"lattice N = {n:.0f}")
        if k == len(hmplot.group_by(d, "n_particles")) - 1:
            axes[row][0].plot(dn["r_u"], dn["u_r_exact"], "k-", lw=1, label="Lamé (same averaging)")
            axes[row][1].plot(dn["r_sigma"], dn["sigma_theta_exact"], "k-", lw=1, label="Lamé (same averaging)")
    axes[row][0].set(xlabel="$r/R$", ylabel="$u_r/R$", title=f"radial displacement, {label_outer} outer boundary")
    axes[row][1].set(xlabel="$r/R$", ylabel="$\\sigma_\\theta/E$", title=f"hoop stress, {label_outer} outer boundary")
    axes[row][0].legend()
    axes[row][1].legend()
hmplot.save(fig, args.out, "verify_lattice_lame", sources=[args.data])
