"""Verification figure: a crack grown from a notch by its volume against Griffith's toughness-dominated
growth (lattice2d.griffith_growth).

Reads lattice2d_griffith_growth.csv: one row per growth point, the variant by its flags (sawtooth, wet,
continuous), n_particles, seed, volume V, half_length c, half_length_griffith (Griffith's c at that V)
and k_over_k_c (p sqrt(pi c) / K_c).
"""
import os

import matplotlib.pyplot as plt
import numpy as np

import hmplot

FIT_FROM, FIT_TO = 0.1, 0.3  # the benchmark's fit range (kGrowthFitFrom, kGrowthFitTo)


def variant_label(sawtooth, wet, continuous):
    if not sawtooth:
        return "brittle (the paper's)"
    return ("envelope, no teeth" if continuous else "saw-tooth") + (", wet zone" if wet else ", dry zone")


args = hmplot.arguments(__doc__)
rows = hmplot.read_csv(os.path.join(args.data, "lattice2d_griffith_growth.csv"))
key = rows["sawtooth"] * 4 + rows["wet"] * 2 + rows["continuous"]  # one number per variant
rows["variant"] = key

fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4))
griffith_drawn = False
for _, d in hmplot.group_by(rows, "variant").items():
    label = variant_label(d["sawtooth"][0], d["wet"][0], d["continuous"][0])
    for n, g in hmplot.group_by(d, "n_particles").items():
        name = f"{label}, $N = {int(n)}$"
        line, = left.plot(g["volume"], g["half_length"], lw=1, label=name)
        right.plot(g["half_length"], g["k_over_k_c"], ".", ms=2, color=line.get_color(), label=name)
        if not griffith_drawn:
            v = np.geomspace(g["volume"][g["volume"] > 0].min(), g["volume"].max(), 200)
            # Griffith's c(V) from the same CSV (c grows as V^(2/3)): scale one point's value.
            ref = np.argmax(g["volume"])
            c_ref = g["half_length_griffith"][ref] * (v / g["volume"][ref]) ** (2 / 3)
            left.plot(v, c_ref, "k--", lw=1.2, label="Griffith: $c = (E'V / 2\\sqrt{\\pi} K_c)^{2/3}$")
            griffith_drawn = True
left.set(xscale="log", yscale="log", xlabel="crack volume $V/R^2$", ylabel="half length $c/R$",
         title="crack length against volume")
left.axhspan(FIT_FROM, FIT_TO, color="0.92", zorder=0)
right.axvspan(FIT_FROM, FIT_TO, color="0.92", zorder=0)
right.axhline(1.0, color="k", lw=1.2)
right.axhspan(0.9, 1.1, color="0.8", alpha=0.5, zorder=0, label="$K_c \\pm 10\\%$")
right.set(xlabel="half length $c/R$", ylabel="$p\\sqrt{\\pi c}\\,/\\,K_c$", ylim=(0, None),
          title="$K$ along the growth, $K_c = \\sqrt{E' G_f}$")
left.legend(fontsize=6)
right.legend(fontsize=6, markerscale=4)
hmplot.save(fig, args.out, "verify_griffith_growth", sources=[args.data])
