#!/bin/bash
# events_per_check = 1 (the saw-tooth law's default) against 4 on the saw-tooth study's settings
# (cases/studies/sawtooth_<setting>.toml), lattice seeds 1-3, one thread per run, then this folder's
# summary.csv and table.md:
#   HMLATTICE=build/hmlattice bash docs/reports/events-per-check-2026-12-07/run.sh OUT [N ...]
# N defaults to 3000 (1-3 min per run on one core); SETTINGS="fig17_b0.2" and SEEDS="1" pick a subset
# (the N = 1e4 row: SETTINGS=fig17_b0.2 SEEDS=1 ... OUT 10000, 10-20 min per run).
set -euo pipefail
H=${HMLATTICE:-build/hmlattice}
OUT=${1:?output folder}
shift
SIZES=${*:-3000}
HERE=$(dirname "$0")
for c in ${SETTINGS:-fig17_b0.2 fig14_b0.2 fig12_b0.2}; do
  [ -d "$OUT/cases_$c" ] || "$H" sweep expand "cases/studies/sawtooth_$c.toml" --out "$OUT/cases_$c" > /dev/null
  for n in $SIZES; do for s in ${SEEDS:-1 2 3}; do for k in 1 4; do
    name="n_particles=${n}_seed=$s"
    runs="$OUT/runs_${c}_epc$k"
    [ -d "$runs/$name" ] && continue
    mkdir -p "$runs"
    /usr/bin/time -f "%e s %M kB" -o "$runs/$name.time" env OMP_NUM_THREADS=1 "$H" run "$OUT/cases_$c/$name.toml" \
      --out "$runs/$name" --set coupling.events_per_check=$k > "$runs/$name.log" 2>&1
  done; done; done
done
/usr/bin/python3 "$HERE/compare.py" "$OUT" "$HERE"
