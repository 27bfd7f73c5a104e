#!/bin/bash
# Fig. 16 b = 0.2 (cases/fig16_b0.2_quick.toml: brittle beams, Q = 1, t* = 5e-4) at N = 3000, 1e4, 2e4,
# seeds 1-3 (lattice and strengths together), with the paper's crack flow (iota = 1e3) or a crack
# transmissivity T = 36 (iota's at N = 3000: 999 times the mean beam length 0.0363). One thread per run.
#   HMLATTICE=build/hmlattice bash docs/reports/fig16-crack-flow-2026-12-05/run.sh OUT   (~45 min, one core)
set -euo pipefail
H=${HMLATTICE:-build/hmlattice}
CASE=cases/fig16_b0.2_quick.toml
OUT=${1:?output folder}
mkdir -p "$OUT"
for seed in 1 2 3; do for n in 3000 10000 20000; do for flow in iota T; do
  extra=()
  if [ $flow = T ]; then extra=(--set physics.iota=1 --set 'flow.fracture_flow="transmissivity"' --set flow.crack_transmissivity=36); fi
  OMP_NUM_THREADS=1 "$H" run $CASE --out "$OUT/n${n}_${flow}_s${seed}" --set lattice.n_particles=$n \
    --set lattice.seed=$seed --set fracture.seed=$seed "${extra[@]}"
done; done; done
