#!/bin/bash
# Anderson depth against passes: the quick Figs. 14, 16, 17 and Fig. 12 b = 0.2 with iota and with the
# cubic law, at one depth, one thread per run (docs/reports/cubic-law-quick-2026-12-06/run.sh with DEPTH);
# then depth<D>/summary.csv here:
#   HMLATTICE=build/hmlattice bash docs/reports/anderson-depth-2026-12-08/run.sh OUT 20
# (~5 min per depth on one core.) The tables in docs/coupling.md compare depths 10, 20 and 30 (depth10/ is
# the 2026-12-07 crack-normal runs, whose cases had depth 10, and Fig. 12 b = 0.2 at 10).
# The two other trials of docs/flow.md on Fig. 14 b = 0.8 with the cubic law at depth 10: a looser
# criterion, --set coupling.pressure_tolerance=1e-3 (3096 passes, final p_h 1.7e-6), and conductances from
# the step's start (a trial build that passed u^n to the openings: 37 372 passes, not kept).
set -euo pipefail
OUT=${1:?output folder}
D=${2:?Anderson depth}
DEPTH=$D CASES_LIST="fig14_b0.2 fig14_b0.8 fig17_b0.2 fig17_b0.8 fig16_b0.2 fig16_b0.8 fig12_b0.2" \
  SUMMARY="$(cd "$(dirname "$0")" && pwd)/depth$D" bash "$(dirname "$0")/../cubic-law-quick-2026-12-06/run.sh" "$OUT/depth$D"
