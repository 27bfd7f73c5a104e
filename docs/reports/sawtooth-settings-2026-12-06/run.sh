#!/bin/bash
# The saw-tooth study of the other settings (cases/studies/sawtooth_<setting>.toml: N = 3000, 1e4 and 3e4,
# lattice seeds 1-3), one thread per run, then <setting>/summary.csv and table.md in this folder:
#   HMLATTICE=build/hmlattice bash docs/reports/sawtooth-settings-2026-12-06/run.sh OUT [N ...]
# N defaults to 3000 (1 min per run; Fig. 16's ~50 min); 1e4 takes ~20 min, 3e4 ~2 h. SETTINGS="fig16_b0.2"
# picks settings. A stopped run continues with --resume.
set -euo pipefail
H=${HMLATTICE:-build/hmlattice}
OUT=${1:?output folder}
shift
SIZES=${*:-3000}
HERE=$(dirname "$0")
for c in ${SETTINGS:-fig12_b0.8 fig14_b0.2 fig17_b0.2 fig16_b0.2 fig19}; do
  "$H" sweep expand "cases/studies/sawtooth_$c.toml" --out "$OUT/cases_$c" --overwrite
  for n in $SIZES; do for s in 1 2 3; do
    name="n_particles=${n}_seed=${s}"
    if [ -f "$OUT/runs_$c/$name/checkpoint.bin" ]; then OMP_NUM_THREADS=1 "$H" run --resume "$OUT/runs_$c/$name"
    elif [ ! -d "$OUT/runs_$c/$name" ]; then
      OMP_NUM_THREADS=1 "$H" run "$OUT/cases_$c/$name.toml" --out "$OUT/runs_$c/$name"
    fi
  done; done
  /usr/bin/python3 docs/reports/sawtooth-fig12-2026-12-06/summarise.py "$OUT/runs_$c" "$HERE/$c" "saw-tooth $c, G_f/(ER) = 2.34e-9"
done
