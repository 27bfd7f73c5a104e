#!/bin/bash
# Anderson depth against passes: the quick Figs. 14, 16, 17 with iota and with the cubic law (as
# docs/reports/cubic-law-quick-2026-12-06/run.sh) and Fig. 12 b = 0.2 with both, at one depth, one thread
# per run; then depth<D>/summary.csv here:
#   HMLATTICE=build/hmlattice bash docs/reports/anderson-depth-2026-12-08/run.sh OUT 20
# (~5 min per depth on one core.) The tables in docs/coupling.md compare depths 10, 20 and 30 (depth10/ is
# the 2026-12-07 crack-normal runs, whose cases had depth 10, and Fig. 12 b = 0.2 at 10).
# The two other trials of docs/flow.md on Fig. 14 b = 0.8 with the cubic law at depth 10: a looser
# criterion, --set coupling.pressure_tolerance=1e-3 (3096 passes, final p_h 1.7e-6), and conductances from
# the step's start (a trial build that passed u^n to the openings: 37 372 passes, not kept).
set -euo pipefail
H=$(realpath "${HMLATTICE:-build/hmlattice}")
OUT=${1:?output folder}
D=${2:?Anderson depth}
HERE=$(cd "$(dirname "$0")" && pwd)
CASES=$(pwd)/cases
mkdir -p "$OUT/depth$D"
cd "$OUT/depth$D"
for c in fig14_b0.2 fig14_b0.8 fig17_b0.2 fig17_b0.8 fig16_b0.2 fig16_b0.8 fig12_b0.2; do
  k=1e-14; case $c in fig17*) k=1e-17;; esac
  OMP_NUM_THREADS=1 "$H" run "$CASES/${c}_quick.toml" --out "${c}_iota" --set "coupling.anderson_depth=$D" \
    > "${c}_iota.log" 2>&1
  OMP_NUM_THREADS=1 "$H" run "$CASES/${c}_quick.toml" --out "${c}_cubic" --set "coupling.anderson_depth=$D" \
    --set physics.iota=1 --set 'flow.fracture_flow="cubic"' --set "flow.rock_permeability=$k" > "${c}_cubic.log" 2>&1
done
/usr/bin/python3 "$HERE/../cubic-law-quick-2026-12-06/summarise.py" . "$HERE/depth$D"
