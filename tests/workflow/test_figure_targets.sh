#!/usr/bin/env bash
# The figure targets of workflow/Snakefile, in a temporary folder:
#   1. fig10 and fig11 for real (the 1D case, a second): one run job, both figures drawn, nothing to do
#      on a second pass;
#   2. dry runs of the targets of Figs. 10-17 in both tiers: one run job per case, from cases/ (quick) or
#      cases/paper/ (paper), one figure job per figure, the 1D references shared by both tiers;
#   3. the verify target: its planning job for real (hmlattice verify --write-cases, a second), then a
#      dry run plans one run job per planned run and the report with --runs;
#   4. a tier that is neither quick nor paper is refused.
# The quick figure runs themselves are each case's smoke test (tests/CMakeLists.txt); the sweeps of
# Figs. 18-20 are tested by test_sweep_workflow.sh and tests/figures/test_fig19_fig20_sweep.sh.
# Usage: test_figure_targets.sh <hmlattice executable> <source folder>. Exit 77 (skipped) only when
# snakemake is missing.
. "$(dirname "${BASH_SOURCE[0]}")/common.sh"
smk() {
  local tier=$1
  shift
  # Targets first: --config takes every name=value after it.
  snakemake -j 1 --snakefile "$src/workflow/Snakefile" --directory "$work" "$@" \
    --config out="$work/out" hmlattice="$hm" tier="$tier"
}

# 1. Figs. 10 and 11 from one 1D run.
smk quick fig10 fig11 > "$work/first.log" 2>&1 || { cat "$work/first.log"; fail "fig10 fig11"; }
for f in fig10/fig10_fdm1d_pressure_displacement.png fig11/fig11_fdm1d_stresses.png; do
  [ -s "$work/out/fig10_fdm1d/figures/$f" ] || { cat "$work/first.log"; fail "no $f"; }
done
[ "$(grep -c '^rule run:' "$work/first.log")" -eq 1 ] || fail "not one run job for fig10 and fig11"
smk quick -n fig10 fig11 > "$work/again.log" 2>&1 || { cat "$work/again.log"; fail "dry run"; }
grep -q "Nothing to be done" "$work/again.log" || { cat "$work/again.log"; fail "a second pass plans jobs"; }
echo "fig10, fig11: drawn from one run, nothing to do again"

# 2. The plans of Figs. 10-17 in both tiers.
targets="fig10 fig11 fig12 fig13 fig14 fig15 fig16 fig17"
for tier in quick paper; do
  smk "$tier" -n -p $targets > "$work/$tier.log" 2>&1 || { cat "$work/$tier.log"; fail "dry run, $tier tier"; }
  # fig10's 1D run is done; 4 figures x 2 b (lattice) + 2 figures x 2 b (1D) are left.
  [ "$(grep -cE '^rule run:' "$work/$tier.log")" -eq 12 ] || { cat "$work/$tier.log"; fail "$tier: not 12 run jobs"; }
  [ "$(grep -cE '^localrule figure:' "$work/$tier.log")" -eq 6 ] || { cat "$work/$tier.log"; fail "$tier: not 6 figure jobs"; }
  for b in 0.2 0.8; do
    for fig in fig12 fig14 fig16 fig17; do
      case_file=$([ "$tier" = quick ] && echo "cases/${fig}_b${b}_quick.toml" || echo "cases/paper/${fig}_b${b}.toml")
      grep -q "run $src/$case_file --out $work/out/${fig}_$tier/runs/b$b " "$work/$tier.log" ||
        fail "$tier: no run of $case_file into ${fig}_$tier/runs/b$b"
    done
    for fig in fig13 fig15; do
      grep -q "fdm1d $src/cases/${fig}_fdm1d_b$b.toml --out $work/out/${fig}_fdm1d/runs/b$b " "$work/$tier.log" ||
        fail "$tier: no 1D run of ${fig}_fdm1d_b$b"
    done
  done
  echo "$tier tier: 12 runs and 6 figures planned for $targets"
done

# 3. The verify target's plan (the quick tier's: the fig12 benchmark's six runs and the fig18 benchmark's
#    21: 3 b x 3 Q x 2 seeds and 3 with the flux-boundary node).
smk quick "$work/out/verify_quick/cases" > "$work/plan.log" 2>&1 || { cat "$work/plan.log"; fail "planning verify's runs"; }
[ "$(tail -n +2 "$work/out/verify_quick/cases/index.csv" | wc -l)" -eq 27 ] || fail "verify_quick/cases: not 27 runs"
smk quick -n -p verify > "$work/verify.log" 2>&1 || { cat "$work/verify.log"; fail "dry run of verify"; }
[ "$(grep -cE '^rule run:' "$work/verify.log")" -eq 27 ] || { cat "$work/verify.log"; fail "verify: not 27 run jobs"; }
grep -q "verify --tier quick --runs $work/out/verify_quick/runs --out $work/out/verify_quick/report " "$work/verify.log" ||
  { cat "$work/verify.log"; fail "verify: no report with --runs"; }
echo "verify: 27 runs and the report with --runs planned"

# 4. A bad tier.
rc=0
smk fast -n fig12 > "$work/bad.log" 2>&1 || rc=$?
[ $rc -ne 0 ] && grep -q "tier=fast: allowed: quick or paper" "$work/bad.log" || { cat "$work/bad.log"; fail "tier=fast accepted"; }
echo "figure targets: passed"
