#!/bin/bash
# The saw-tooth Fig. 12 b = 0.2 study (cases/studies/sawtooth_fig12_b0.2.toml: N = 3000, 1e4 and 3e4, lattice
# seeds 1-3, to t* = 0.009), one thread per run, then this folder's summary.csv and table.md:
#   HMLATTICE=build/hmlattice bash docs/reports/sawtooth-fig12-2026-12-06/run.sh OUT
# (N = 3000: 2-3 min each; N = 1e4: ~20 min; N = 3e4: ~2 h. A run stopped part-way continues with --resume.)
# The same runs through the workflow: snakemake -j 2 --snakefile workflow/Snakefile
#   --config sweep=cases/studies/sawtooth_fig12_b0.2.toml
set -euo pipefail
H=${HMLATTICE:-build/hmlattice}
OUT=${1:?output folder}
HERE=$(dirname "$0")
"$H" sweep expand cases/studies/sawtooth_fig12_b0.2.toml --out "$OUT/cases" --overwrite
for n in 3000 10000 30000; do for s in 1 2 3; do
  name="n_particles=${n}_seed=${s}"
  if [ -f "$OUT/runs/$name/checkpoint.bin" ]; then OMP_NUM_THREADS=1 "$H" run --resume "$OUT/runs/$name"
  elif [ ! -d "$OUT/runs/$name" ]; then OMP_NUM_THREADS=1 "$H" run "$OUT/cases/$name.toml" --out "$OUT/runs/$name"; fi
done; done
/usr/bin/python3 "$HERE/summarise.py" "$OUT/runs" "$HERE"
