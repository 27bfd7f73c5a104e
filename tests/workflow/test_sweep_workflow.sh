#!/usr/bin/env bash
# The Snakemake workflow (workflow/Snakefile) on a small sweep, 2 Q x 2 seeds at N = 1000 (the
# quick Fig. 18 case with other lists), with -j 2 in a temporary folder:
#   1. every combination is run and collected, each complete with a breakdown pressure;
#   2. a second snakemake has nothing to do, and a real second run leaves every run folder as it was;
#   3. with one run folder removed, only that run (and the collect) is done again.
# Usage: test_sweep_workflow.sh <hmlattice executable> <source folder>. Exit 77 (skipped) only when
# snakemake is missing; scripts/test.sh installs it.
. "$(dirname "${BASH_SOURCE[0]}")/common.sh"

# The quick Fig. 18 case with a smaller [sweep] (its last table).
sed '/^\[sweep\]/,$d' "$src/cases/sweep_fig18_quick.toml" > "$work/mini.toml"
printf '[sweep]\n"physics.Q" = [0.01, 0.1]\n"lattice.seed" = [1, 2]\n' >> "$work/mini.toml"

smk() {
  snakemake -j 2 --snakefile "$src/workflow/Snakefile" --directory "$work" \
    --config sweep="$work/mini.toml" out="$work/out" hmlattice="$hm" "$@"
}
runs=$work/out/mini/runs
results=$work/out/mini/results.csv
stamps() { for d in "$runs"/*/; do stat -c '%n %i %Y' "$d/.hmlattice"; done; }

# 1. Everything, from nothing.
start=$SECONDS
smk > "$work/first.log" 2>&1 || { cat "$work/first.log"; fail "first snakemake"; }
echo "first pass: $((SECONDS - start)) s"
[ "$(tail -n +2 "$results" | wc -l)" -eq 4 ] || { cat "$results"; fail "results.csv: not 4 rows"; }
for name in Q=0.01_seed=1 Q=0.01_seed=2 Q=0.1_seed=1 Q=0.1_seed=2; do
  /usr/bin/python3 - "$results" "$name" <<'PY' || fail "row $name"
import csv, math, sys
rows = {r["name"]: r for r in csv.DictReader(open(sys.argv[1]))}
r = rows[sys.argv[2]]
assert r["status"] == "complete", r
assert not math.isnan(float(r["p_h_first_break"])), r
print(sys.argv[2], "complete, p_h at first break", r["p_h_first_break"])
PY
done

# 2. Nothing to do again.
before=$(stamps)
smk -n > "$work/dry.log" 2>&1 || { cat "$work/dry.log"; fail "dry run"; }
grep -q "Nothing to be done" "$work/dry.log" || { cat "$work/dry.log"; fail "the dry run plans jobs"; }
smk > "$work/second.log" 2>&1 || { cat "$work/second.log"; fail "second snakemake"; }
[ "$(stamps)" = "$before" ] || fail "a second snakemake changed run folders"
echo "second pass: nothing redone"

# 3. One run folder removed: only it is run again.
rm -rf "$runs/Q=0.1_seed=2"
smk -n > "$work/dry2.log" 2>&1 || { cat "$work/dry2.log"; fail "dry run after removal"; }
grep -qE '^run +1( |$)' "$work/dry2.log" || { cat "$work/dry2.log"; fail "not exactly one run planned"; }
smk > "$work/third.log" 2>&1 || { cat "$work/third.log"; fail "third snakemake"; }
after=$(stamps)
[ "$(grep -v 'Q=0.1_seed=2' <<<"$after")" = "$(grep -v 'Q=0.1_seed=2' <<<"$before")" ] || fail "other run folders changed"
grep -q 'Q=0.1_seed=2' <<<"$after" || fail "the removed run was not redone"
[ "$(grep -c ',complete,' "$results")" -eq 4 ] || { cat "$results"; fail "results.csv after the rerun"; }
echo "third pass: only Q=0.1_seed=2 redone; total $((SECONDS - start)) s"
