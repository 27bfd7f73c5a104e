"""Half-lengths of the trial's K-vertex run (kv2) and viscous run with a slotted notch (km3) at the same
injected volume, the toughness the K-vertex run implies, and their ratio (docs/flow.md).
Usage: /usr/bin/python3 lengths.py [HMLATTICE [K_RUN VISCOUS_RUN]]   (HMLATTICE prints Dontsov's scales,
default build/hmlattice; the runs' <name>_breaks.csv in this folder, default kv2 km3)"""
import io
import math
import os
import subprocess
import sys

import pandas as pd

here = os.path.dirname(os.path.abspath(__file__))
E_prime, Q = 1.0 / (1.0 - 0.25**2), 1.0


def wings(run, t):
    """The crack's tips along the notch's line (broken beams within 0.15 of it), right and left."""
    b = pd.read_csv(os.path.join(here, f"{run}_breaks.csv"))
    b = b[(b.time <= t + 1e-15) & (b.y.abs() < 0.15)]
    return b.x.max(), -b.x.min()


hmlattice = sys.argv[1] if len(sys.argv) > 1 else "build/hmlattice"
k_run, viscous_run = sys.argv[2:4] if len(sys.argv) > 3 else ("kv2", "km3")
scales = subprocess.run([hmlattice, "analytic", "kgd", "--Km", "1,1.2,1.4,1.6"], capture_output=True, text=True)
print(pd.read_csv(io.StringIO(scales.stdout)).to_string(index=False))
for t in [2e-5, 3e-5, 4e-5, 5e-5, 6e-5, 7e-5, 8e-5]:
    k_right, k_left = wings(k_run, t)
    v_right, v_left = wings(viscous_run, t)
    c_k, c_v = 0.5 * (k_right + k_left), 0.5 * (v_right + v_left)
    # Griffith's crack holding V = Q t: c = (E' V / (2 sqrt(pi) K))^(2/3).
    toughness = E_prime * Q * t / (2.0 * math.sqrt(math.pi) * c_k**1.5)
    print(f"t = {t:.0e}: toughness-dominated c = {c_k:.3f} (K = {toughness:.2e}), "
          f"viscous c = {c_v:.3f} (wings {v_right:.3f}, {v_left:.3f}), ratio {c_v / c_k:.2f}")
