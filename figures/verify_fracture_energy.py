"""Verification figure: the energy a crack grown from a notch spends per unit length, against N
(lattice2d.fracture_energy).

Reads lattice2d_fracture_energy.csv: one row per growth, with sawtooth (0: the brittle law), n_particles,
seed, and per unit crack length over G_f the law's booked energy, the rock's dissipation and the growth's
cost (W - pV/2).
"""
import os

import matplotlib.pyplot as plt
import numpy as np

import hmplot

args = hmplot.arguments(__doc__)
rows = hmplot.read_csv(os.path.join(args.data, "lattice2d_fracture_energy.csv"))

fig, ax = plt.subplots(figsize=(6, 4))
series = [(1, "booked", "saw-tooth: booked", "o"), (1, "rock", "saw-tooth: rock's dissipation", "s"),
          (0, "rock", "brittle (the paper's): rock's dissipation", "^")]
for law, column, label, marker in series:
    d = hmplot.group_by(rows, "sawtooth").get(float(law))
    if d is None:
        continue
    by_n = hmplot.group_by(d, "n_particles")
    n = np.array(sorted(by_n))
    mean = np.array([by_n[k][column].mean() for k in n])
    line, = ax.plot(n, mean, marker=marker, label=label)
    ax.plot(d["n_particles"], d[column], marker, color=line.get_color(), ms=3, alpha=0.5, ls="none")
ax.axhline(1.0, color="k", lw=1, label="$G_f$")
ax.set(xscale="log", xlabel="particles $N$", ylabel="energy per unit crack length $/\\,G_f$", ylim=(0, None),
       title="Energy a growing crack spends, against resolution")
ax.legend(fontsize=7)
hmplot.save(fig, args.out, "verify_fracture_energy", sources=[args.data])
