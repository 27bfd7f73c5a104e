#!/bin/bash
# Does the fracture count depend on the time step? Brittle Fig. 12 b = 0.2 (cases/fig12_b0.2_quick.toml to
# t* = 0.0272, no VTK) at N = 3000 and 1e4, lattice and strength seeds 1-3, dt_max = 5e-4, 2.5e-4, 1.25e-4,
# breaks checked every pass (all that fail at the pass's pressures, Fig. 5) or at the coupled equilibrium one
# at a time (fracture_check = "at_convergence", events_per_check = 1); in two settings: the paper's
# ("paper": the shipped quick case) and the water-filled borehole with L_m = 1e-3 ("candidate":
# borehole_storage = "fluid", crack_tip_length = 1e-3), the latter also with the borehole's undrained spring.
# One thread per run (N = 3000: 1-10 s, N = 1e4: 20-200 s), then summary.csv and table.md here:
#   HMLATTICE=build/hmlattice bash docs/reports/check-timing-dt-2026-12-06/run.sh OUT
set -euo pipefail
H=${HMLATTICE:-build/hmlattice}
OUT=${1:?output folder}
HERE=$(dirname "$0")
mkdir -p "$OUT/runs" "$OUT/logs"
sed -e 's/^vtk = true/vtk = false/' cases/fig12_b0.2_quick.toml > "$OUT/paper.toml"
sed -e 's/^borehole_storage = "none"/borehole_storage = "fluid"/' -e '/^borehole_deformation/d' \
    -e 's/^width = 0.05/width = 0.05\ncrack_tip_length = 1e-3/' "$OUT/paper.toml" > "$OUT/candidate.toml"
for n in 3000 10000; do for setting in paper candidate; do for seed in 1 2 3; do for dt in 5e-4 2.5e-4 1.25e-4; do
  modes="pass conv"; [ $setting = candidate ] && modes="pass conv spring"
  for mode in $modes; do
    name=${setting}_n${n}_s${seed}_dt${dt}_${mode}
    [ -f "$OUT/runs/$name/fracture_summary.csv" ] && continue
    extra=()
    [ $mode = conv ] && extra=(--set 'coupling.fracture_check="at_convergence"' --set coupling.events_per_check=1)
    [ $mode = spring ] && extra=(--set 'coupling.borehole_spring="undrained"')
    OMP_NUM_THREADS=1 "$H" run "$OUT/$setting.toml" --out "$OUT/runs/$name" --set lattice.n_particles=$n \
      --set lattice.seed=$seed --set fracture.seed=$seed --set numerics.dt_max=$dt "${extra[@]}" > "$OUT/logs/$name.log" 2>&1
  done
done; done; done; done
/usr/bin/python3 "$HERE/summarise.py" "$OUT/runs" "$HERE"
