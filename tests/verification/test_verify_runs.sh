#!/usr/bin/env bash
# hmlattice verify --runs: the benchmarks' runs of case files read from run folders that `hmlattice run`
# made (as a workflow engine does), in a temporary folder:
#   1. --write-cases plans the quick fig12 benchmark's six runs; four of them are read from folders made
#      by `hmlattice run`: the two cases (the smoke tests' run folders of cases/fig12_b*_quick.toml,
#      copied) and their flux-borehole twins (run here from the planned cases), and verify --runs runs
#      the other two itself: every metric is the quick tier's (the reference report, the
#      "verification: quick tier" test's metrics.json), the pressure in the fractures included
#      (fracture_pressure.csv);
#   2. a run folder of another case (physics.Q changed in its config.toml) is refused before anything
#      runs: exit 2, one line naming the folder and the key, no report folder;
#   3. a folder that is not a complete run (no marker) is refused likewise.
# Usage: test_verify_runs.sh <hmlattice> <reference metrics.json> <folder of the smoke tests' run folders>
set -euo pipefail
hm=$1
reference=$2
smoke=$3
. "$(dirname "$0")/../scratch_folder.sh" verify-runs

# 1. Four runs made outside verify, read back; the other two run here.
"$hm" verify --tier quick --filter fig12_quick --write-cases "$work/cases" > /dev/null
[ "$(tail -n +2 "$work/cases/index.csv" | wc -l)" -eq 6 ] || { cat "$work/cases/index.csv"; fail "not 6 planned runs"; }
mkdir "$work/runs"
cp -a "$smoke/fig12_b0.2_quick" "$smoke/fig12_b0.8_quick" "$work/runs/"
for name in fig12_b0.2_quick_flux_borehole fig12_b0.8_quick_flux_borehole; do
  "$hm" run "$work/cases/$name.toml" --out "$work/runs/$name" > "$work/$name.log" 2>&1 || { cat "$work/$name.log"; fail "hmlattice run $name"; }
done
"$hm" verify --tier quick --filter fig12_quick --runs "$work/runs" --out "$work/report" > "$work/verify.log" 2>&1 ||
  { cat "$work/verify.log"; fail "verify --runs"; }
grep -q -- "--runs $work/runs: 4 of the 6 planned runs found there (complete, same case), 2 to run here" "$work/verify.log" ||
  { cat "$work/verify.log"; fail "verify --runs did not say what it read"; }
/usr/bin/python3 - "$reference" "$work/report/metrics.json" <<'PY' || fail "metrics differ from the quick tier's"
import json, sys
ref = {m["metric"]: m for m in json.load(open(sys.argv[1])) if m["benchmark"] == "lattice2d.fig12_quick"}
got = {m["metric"]: m for m in json.load(open(sys.argv[2]))}
assert ref, "no lattice2d.fig12_quick metrics in the reference"
extra = sorted(set(got) - set(ref))
assert not extra, f"metrics not in the reference: {extra}"
differ = [(k, ref[k]["value"], got[k]["value"]) for k in got if repr(ref[k]["value"]) != repr(got[k]["value"])]
assert not differ, f"different values: {differ}"
missing = sorted(set(ref) - set(got))
assert not missing, f"left out: {missing}"
print(f"{len(got)} metrics as the quick tier's, none left out")
PY

# 2. A stale run folder: another case in its config.toml.
mkdir "$work/stale"
cp -a "$work/runs/fig12_b0.2_quick_flux_borehole" "$work/stale/"
sed -i 's/^Q = .*/Q = 0.02/' "$work/stale/fig12_b0.2_quick_flux_borehole/config.toml"
rc=0
"$hm" verify --tier quick --filter fig12_quick --runs "$work/stale" --out "$work/report_stale" > "$work/stale.log" 2>&1 || rc=$?
[ $rc -eq 2 ] || { cat "$work/stale.log"; fail "a stale run folder: exit $rc, not 2"; }
grep -q "stale/fig12_b0.2_quick_flux_borehole is a run of another case than lattice2d.fig12_quick's: physics.Q = 0.02, the benchmark's case has 0.01" "$work/stale.log" ||
  { cat "$work/stale.log"; fail "the message does not name the folder and physics.Q"; }
[ ! -e "$work/report_stale" ] || fail "a report folder was made for a refused --runs"
echo "stale run folder refused: $(head -c 200 "$work/stale.log")"

# 3. A folder that is not a complete run.
mkdir -p "$work/partial/fig12_b0.8_quick"
cp "$work/cases/fig12_b0.8_quick.toml" "$work/partial/fig12_b0.8_quick/config.toml"
rc=0
"$hm" verify --tier quick --filter fig12_quick --runs "$work/partial" --out "$work/report_partial" > "$work/partial.log" 2>&1 || rc=$?
[ $rc -eq 2 ] && grep -q "partial/fig12_b0.8_quick is not a complete run" "$work/partial.log" ||
  { cat "$work/partial.log"; fail "an incomplete run folder: exit $rc"; }
[ ! -e "$work/report_partial" ] || fail "a report folder was made for a refused --runs"
echo "verify --runs: passed"
