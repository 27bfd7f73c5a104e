#!/usr/bin/env bash
# Figs. 19 and 20 from the quick refinement sweep (cases/sweep_fig19_quick.toml, N = 684 and 3000),
# laid out as the Snakemake workflow lays out a sweep (cases/, runs/<name>/, results.csv) but run here
# without Snakemake, one run after the other, in a temporary folder:
#   1. both figure scripts draw every combination (their printed count) and write their PNG;
#   2. a sweep folder whose results.csv lacks lattice.n_particles is refused (exit 2, no --out made).
# Usage: test_fig19_fig20_sweep.sh <hmlattice executable> <source folder> <python with matplotlib>.
set -euo pipefail
hm=$1
src=$2
py=$3
. "$(dirname "$0")/../scratch_folder.sh" fig19

sweep=$work/sweep_fig19_quick
"$hm" sweep expand "$src/cases/sweep_fig19_quick.toml" --out "$sweep/cases"
mkdir -p "$sweep/runs"
tail -n +2 "$sweep/cases/index.csv" | cut -d, -f1 | while read -r name; do
  "$hm" run "$sweep/cases/$name.toml" --out "$sweep/runs/$name" > "$work/$name.log"
done
"$hm" sweep collect "$sweep/cases" --runs "$sweep/runs" > "$sweep/results.csv"

# 1. Both figures, every combination drawn.
"$py" "$src/figures/fig19_resolution_pressure.py" --data "$sweep" --out "$work/fig" | tee "$work/fig19.txt"
grep -q "fig19: 2 of 2 combinations drawn" "$work/fig19.txt" || fail "fig19 did not draw both runs"
"$py" "$src/figures/fig20_displacement_resolution.py" --data "$sweep" --out "$work/fig" | tee "$work/fig20.txt"
grep -q "fig20: 2 of 2 combinations drawn" "$work/fig20.txt" || fail "fig20 did not draw both runs"
for name in fig19_resolution_pressure fig20_displacement_resolution; do
  test -s "$work/fig/$name.png" || fail "no $name.png"
done

# 2. A sweep over another key is refused before anything is written.
mkdir -p "$work/other"
sed 's/lattice.n_particles/lattice.seed/' "$sweep/results.csv" > "$work/other/results.csv"
set +e
"$py" "$src/figures/fig20_displacement_resolution.py" --data "$work/other" --out "$work/bad" 2> "$work/bad.txt"
rc=$?
set -e
test $rc -eq 2 || fail "a results.csv without lattice.n_particles: exit $rc, not 2"
grep -q "has no column lattice.n_particles" "$work/bad.txt" || fail "no reason given: $(cat "$work/bad.txt")"
test ! -e "$work/bad" || fail "--out made for refused input"
echo "fig19 and fig20: passed"
