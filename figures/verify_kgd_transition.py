"""Verification figure: the KGD fracture between its vertices (lattice2d.kgd_transition).

Reads lattice2d_kgd_transition.csv (every state of both runs: viscous 1 for the cubic-law crack, 0 for its
toughness-dominated twin; n_particles, seed, t, half_length) and lattice2d_kgd_transition_ratio.csv (the
compared samples, every 1e-6 while the twin's half length is in [0.1, 0.3]: t, ratio of the lattice's
lengths, mean_ratio their geometric mean, expected = Dontsov's ratio at the twin's toughness number).
"""
import os

import matplotlib.pyplot as plt

import hmplot

args = hmplot.arguments(__doc__)
runs = hmplot.read_csv(os.path.join(args.data, "lattice2d_kgd_transition.csv"))
samples = hmplot.read_csv(os.path.join(args.data, "lattice2d_kgd_transition_ratio.csv"))
runs["lattice"] = runs["n_particles"] * 100 + runs["seed"]  # one number per lattice
samples["lattice"] = samples["n_particles"] * 100 + samples["seed"]

fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4))
colours = {}
for key, d in hmplot.group_by(runs, "lattice").items():
    name = f"$N = {int(d['n_particles'][0])}$, seed {int(d['seed'][0])}"
    for viscous, g in hmplot.group_by(d, "viscous").items():
        line, = left.plot(g["t"], g["half_length"], "-" if viscous else "--", lw=1, color=colours.get(key),
                          label=name + (", viscous" if viscous else ", toughness twin"))
        colours[key] = line.get_color()
for key, d in hmplot.group_by(samples, "lattice").items():
    name = f"$N = {int(d['n_particles'][0])}$, seed {int(d['seed'][0])}"
    colour = colours.get(key)
    right.plot(d["t"], d["ratio"], ".", ms=2, color=colour, label=name + ", lattice")
    right.plot(d["t"], d["mean_ratio"], "-", lw=1.2, color=colour, label=name + ", lattice, geometric mean")
    right.plot(d["t"], d["expected"], ":", lw=1.5, color=colour, label=name + ", Dontsov (2017) at the twin's $K_m$")
left.axhspan(0.1, 0.3, color="0.92", zorder=0)
left.set(xlabel="$t$", ylabel="half length $c/R$", title="crack half length")
right.axhline(1.0, color="k", lw=0.8)
right.set(xlabel="$t$", ylabel="$c_{viscous} / c_{toughness}$", ylim=(0.5, 1.5),
          title="viscous over toughness-dominated length, same volume")
left.legend(fontsize=6)
right.legend(fontsize=6)
hmplot.save(fig, args.out, "verify_kgd_transition", sources=[args.data])
