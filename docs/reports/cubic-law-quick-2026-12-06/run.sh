#!/bin/bash
# The paper's quick Figs. 14, 16, 17 (N = 3000, seed 1, brittle beams) with the paper's constant iota and
# with the cubic law, one thread each, then summary.csv in this folder:
#   HMLATTICE=build/hmlattice bash docs/reports/cubic-law-quick-2026-12-06/run.sh OUT
# APERTURE=axial|jump|crack_normal sets the cubic law's [flow] crack_aperture (default: the program's);
# SUMMARY=DIR writes summary.csv there instead of this folder; N=<particles> runs the cases at that N
# instead of their 3000; CASES_LIST="fig17_b0.2 ..." runs those only, in that order (fig12_b0.2 too);
# DEPTH=<n> sets [coupling] anderson_depth in both runs of each case.
# rock_permeability is k/R^2 of each figure's rock (R = 1 m): k = 1e-14 m^2 for Figs. 14 and 16, 1e-17 m^2
# for Fig. 17 (Section 3.4's low-permeability rock).
set -euo pipefail
H=$(realpath "${HMLATTICE:-build/hmlattice}")  # the runs start in OUT
OUT=${1:?output folder}
EXTRA_SET=()
[ -n "${APERTURE:-}" ] && EXTRA_SET=(--set "flow.crack_aperture=\"$APERTURE\"")
[ -n "${N:-}" ] && EXTRA_SET+=(--set "lattice.n_particles=$N")
BOTH_SET=()
[ -n "${DEPTH:-}" ] && BOTH_SET=(--set "coupling.anderson_depth=$DEPTH") && EXTRA_SET+=("${BOTH_SET[@]}")
HERE=$(cd "$(dirname "$0")" && pwd)
CASES=$(pwd)/cases
mkdir -p "$OUT"
cd "$OUT"
for c in ${CASES_LIST:-fig14_b0.2 fig14_b0.8 fig17_b0.2 fig17_b0.8 fig16_b0.2 fig16_b0.8}; do
  k=1e-14; case $c in fig17*) k=1e-17;; esac
  OMP_NUM_THREADS=1 "$H" run "$CASES/${c}_quick.toml" --out "${c}_iota" ${N:+--set "lattice.n_particles=$N"} "${BOTH_SET[@]}" \
    > "${c}_iota.log" 2>&1
  OMP_NUM_THREADS=1 "$H" run "$CASES/${c}_quick.toml" --out "${c}_cubic" --set physics.iota=1 \
    --set 'flow.fracture_flow="cubic"' --set "flow.rock_permeability=$k" "${EXTRA_SET[@]}" > "${c}_cubic.log" 2>&1
done
/usr/bin/python3 "$HERE/summarise.py" . "${SUMMARY:-$HERE}"
