"""A study in a few lines: the breakdown pressure of the Fig. 12 borehole against the injection rate Q.

    /usr/bin/python3 examples/q_sweep.py [OUT]       (default out/examples/q_sweep; ~10 s)
"""
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

import hmlattice

out = sys.argv[1] if len(sys.argv) > 1 else "out/examples/q_sweep"
case = os.path.join(os.path.dirname(__file__), "..", "cases", "fig12_b0.2_quick.toml")
table = hmlattice.sweep(case, out, {"physics.Q": [1e-3, 3e-3, 1e-2, 3e-2]}, overwrite=True,
                        lattice__n_particles=1000, fracture__stop_at_first_break=True, output__vtk=False)
print(table[["physics.Q", "status", "t_first_break", "p_h_first_break"]].to_string(index=False))
ax = table.plot(x="physics.Q", y="p_h_first_break", marker="o", logx=True, legend=False)
ax.set(xlabel="$Q$", ylabel="$p_h/E$ at the first break", title="Fig. 12 borehole (b = 0.2, N = 1000): breakdown against Q")
plt.savefig(os.path.join(out, "breakdown_vs_Q.png"), dpi=120, bbox_inches="tight")
print("wrote", os.path.join(out, "breakdown_vs_Q.png"))
