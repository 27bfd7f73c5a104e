"""Fig. C2: the pressurised crack of broken beams against Sneddon's ellipse (Appendix C, Eq. C1).

Reads lattice2d_sneddon.csv written by `hmlattice verify` (benchmark lattice2d.sneddon), one row per
broken beam: case, c_nominal, boundary (0 free, 1 fixed outer boundary), x (crossing of y = 0),
aperture (2w, the y-jump across the beam), aperture_sneddon (Eq. C1 at x, with the lattice's measured
E' and the crack's Voronoi half length c_effective), x_upper, uy_upper, x_lower, uy_lower (the two
particles' x and y displacement), normal_opening, c_effective, x_center, max_aperture_sneddon.

Left: 2w / 2w0 against x / c for every case, with the ellipse. Right: as in the paper's Fig. C2, the
displacement u_y of the particles on both faces along the crack (free boundary, largest c), with the
analytic faces +-w(x).
"""
import os

import matplotlib.pyplot as plt
import numpy as np

import hmplot

args = hmplot.arguments(__doc__)
data = hmplot.read_csv(os.path.join(args.data, "lattice2d_sneddon.csv"))
cases = hmplot.group_by(data, "case")

fig, axes = plt.subplots(1, 2, figsize=(10, 3.6))
s = np.linspace(-1, 1, 401)
axes[0].plot(s, np.sqrt(1 - s**2), "k-", lw=1.2, label="Sneddon, Eq. C1")
markers = {0: "o", 1: "s"}
for key, d in cases.items():
    c_eff = d["c_effective"][0]
    w0 = d["max_aperture_sneddon"][0]
    boundary = "free" if d["boundary"][0] == 0 else "fixed"
    xs = (d["x"] - d["x_center"][0]) / c_eff
    order = np.argsort(xs)
    axes[0].plot(xs[order], d["aperture"][order] / w0, markers[int(d["boundary"][0])] + "-", ms=3, lw=0.6,
                 label=f"lattice, c = {d['c_nominal'][0]:g}, {boundary} outer boundary")
axes[0].set(xlabel="x / c", ylabel="aperture 2w / 2w0 (Sneddon)", title="aperture along the crack", ylim=(0, 1.25))
axes[0].legend(fontsize=6.5, loc="lower center")

# Largest c with the free boundary: particle displacements on both faces.
free = [d for d in cases.values() if d["boundary"][0] == 0]
d = max(free, key=lambda g: g["c_nominal"][0])
c_eff, xc, w0 = d["c_effective"][0], d["x_center"][0], d["max_aperture_sneddon"][0] / 2
x = np.linspace(-c_eff, c_eff, 401)
w = w0 * np.sqrt(np.clip(1 - (x / c_eff) ** 2, 0, None))
axes[1].plot(x + xc, w, "k-", lw=1.2, label="Sneddon faces ±w(x)")
axes[1].plot(x + xc, -w, "k-", lw=1.2)
axes[1].plot(d["x_upper"], d["uy_upper"], "^", ms=3.5, color="C0", label="upper-face particles, u_y")
axes[1].plot(d["x_lower"], d["uy_lower"], "v", ms=3.5, color="C3", label="lower-face particles, u_y")
axes[1].set(xlabel="x (over R)", ylabel="u_y (over R)",
            title=f"particles along the crack (c = {d['c_nominal'][0]:g}, free)")
axes[1].legend(fontsize=6.5)
hmplot.save(fig, args.out, "figC2_sneddon", sources=[args.data])
