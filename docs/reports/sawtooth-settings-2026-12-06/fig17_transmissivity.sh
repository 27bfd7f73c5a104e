#!/bin/bash
# Fig. 17 b = 0.2 saw-tooth with the crack transmissivity held at iota's N = 3000 value (T = 999999 x 0.0363 = 3.63e4), seed 1, N = 3000 and 1e4
# OUT is run.sh's output folder (its cases_fig17_b0.2); usage: HMLATTICE=build/hmlattice bash <this> OUT
set -euo pipefail
H=${HMLATTICE:-build/hmlattice}
OUT=${1:?output folder}
for n in 3000 10000; do
  OMP_NUM_THREADS=1 "$H" run "$OUT/cases_fig17_b0.2/n_particles=${n}_seed=1.toml" --out "$OUT/fig17_T_${n}_1" \
    --set 'flow.fracture_flow="transmissivity"' --set flow.crack_transmissivity=3.63e4 --set physics.iota=1
done
