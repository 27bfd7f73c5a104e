#!/usr/bin/env bash
# Self-test of the Slurm profile (workflow/profiles/slurm): a one-node Slurm on this machine (munged,
# slurmctld, slurmd, all from Debian 12 and all in a temporary folder), the workflow test's small sweep
# (2 Q x 2 seeds at N = 1000, tests/workflow/test_sweep_workflow.sh) through
#   snakemake --profile workflow/profiles/slurm
# then checks that every run was a completed Slurm job and that results.csv has every combination.
# The daemons it started are stopped and its folder removed at the end, also on failure; only the
# installed packages stay. Prints PASS or FAIL last; exits non-zero on failure.
#   sudo scripts/slurm-selftest.sh          # HMLATTICE=/path/to/hmlattice (default: build/hmlattice)
# Needs root (apt-get, daemons that switch to the job's user) and no other Slurm on ports 6817/6818.
set -euo pipefail
src=$(cd "$(dirname "$0")/.." && pwd)
hm=${HMLATTICE:-$src/build/hmlattice}
start=$SECONDS

fail() { echo "slurm-selftest: FAIL: $*"; exit 1; }
[ "$(id -u)" -eq 0 ] || fail "run as root"
[ -x "$hm" ] || fail "no hmlattice at $hm (build it, or set HMLATTICE)"
for port in 6817 6818; do
  ! (exec 3<>"/dev/tcp/127.0.0.1/$port") 2>/dev/null || fail "port $port in use: another Slurm runs here"
done

bash "$src/scripts/install-deps.sh" snakemake munge slurmctld slurmd slurm-client
# Debian 12 has Snakemake 7.21 with its own Slurm executor (--slurm, the profile's `slurm: true`);
# Snakemake 8 moved it into a plugin, which the profile does not use.
snakemake --help | grep -q -- '--slurm ' || fail "snakemake $(snakemake --version) has no --slurm executor (Snakemake 7.x needed)"
echo "slurm-selftest: snakemake $(snakemake --version), $(slurmctld -V)"

# munged refuses a socket in a folder that not everyone can enter: 0755, not mktemp's 0700.
tmp=$(mktemp -d "${TMPDIR:-/tmp}/hmlattice-slurm-XXXXXX")
chmod 755 "$tmp"
pids=()
cleanup() {
  # Jobs first (a failed test may leave some queued or running), then the daemons, by their pids.
  if [ -f "$tmp/slurm.conf" ] && [ ${#pids[@]} -gt 0 ]; then
    SLURM_CONF=$tmp/slurm.conf scancel --quiet --user=root 2>/dev/null || true
  fi
  for pid in "${pids[@]}"; do kill "$pid" 2>/dev/null || true; done
  for pid in "${pids[@]}"; do
    for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.2; done
  done
  rm -rf "$tmp"
}
trap cleanup EXIT
started() {  # $1: pid file of a daemon that forked; its pid is stopped by cleanup
  for _ in $(seq 50); do [ -s "$1" ] && { pids+=("$(cat "$1")"); return; }; sleep 0.2; done
  fail "no pid file $1"
}

mungekey -c -k "$tmp/munge.key"
munged --socket="$tmp/munge.socket" --key-file="$tmp/munge.key" --pid-file="$tmp/munged.pid" \
       --log-file="$tmp/munged.log" --seed-file="$tmp/munged.seed" || fail "munged: $(tail -n 3 "$tmp/munged.log")"
started "$tmp/munged.pid"

# One node, this machine, reached at 127.0.0.1 whatever its name resolves to. No cgroups (none in a
# container) and no accounting (no slurmdbd): the Snakemake executor then asks scontrol for job states.
host=$(hostname -s)
mem=$(slurmd -C | sed -n 's/.*RealMemory=\([0-9]*\).*/\1/p')
cat > "$tmp/slurm.conf" <<EOF
ClusterName=selftest
SlurmctldHost=$host(127.0.0.1)
SlurmUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$tmp/munge.socket
StateSaveLocation=$tmp/state
SlurmdSpoolDir=$tmp/spool
SlurmctldPidFile=$tmp/slurmctld.pid
SlurmdPidFile=$tmp/slurmd.pid
SlurmctldLogFile=$tmp/slurmctld.log
SlurmdLogFile=$tmp/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
MpiDefault=none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core_Memory
AccountingStorageType=accounting_storage/none
JobAcctGatherType=jobacct_gather/none
ReturnToService=2
NodeName=$host NodeAddr=127.0.0.1 CPUs=2 RealMemory=$mem State=UNKNOWN
PartitionName=selftest Nodes=$host Default=YES MaxTime=60 State=UP
EOF
mkdir -p "$tmp/state" "$tmp/spool"
export SLURM_CONF=$tmp/slurm.conf           # sbatch, srun, squeue, scontrol, also inside the jobs
export USER=${USER:-$(id -un)}              # Snakemake's Slurm executor reads it (sacct, sacctmgr)
export XDG_CACHE_HOME=$tmp/cache            # Snakemake's source cache, not the user's
slurmctld -f "$SLURM_CONF" || fail "slurmctld: $(tail -n 5 "$tmp/slurmctld.log")"
started "$tmp/slurmctld.pid"
slurmd -f "$SLURM_CONF" || fail "slurmd: $(tail -n 5 "$tmp/slurmd.log")"
started "$tmp/slurmd.pid"
for _ in $(seq 60); do [ "$(sinfo -h -N -o %T 2>/dev/null)" = idle ] && break; sleep 1; done
[ "$(sinfo -h -N -o %T)" = idle ] || fail "node not idle: $(sinfo -N 2>&1; tail -n 5 "$tmp/slurmctld.log")"
echo "slurm-selftest: node $host idle (CPUs=2 RealMemory=$mem), Slurm up after $((SECONDS - start)) s"

# The workflow test's sweep, in the temporary folder (the jobs see it: same machine).
work=$tmp/work
mkdir "$work"
sed '/^\[sweep\]/,$d' "$src/cases/sweep_fig18_quick.toml" > "$work/mini.toml"
printf '[sweep]\n"physics.Q" = [0.01, 0.1]\n"lattice.seed" = [1, 2]\n' >> "$work/mini.toml"
smk() {
  # One status check a second instead of Snakemake's every 33 s for Slurm: jobs of seconds here. The
  # timeout: a job Slurm cannot start (time limit above MaxTime) would stay pending for ever, and
  # snakemake answers SIGTERM by waiting for its jobs, hence the SIGKILL 10 s later.
  (cd "$work" && timeout --kill-after=10 300 snakemake --profile "$src/workflow/profiles/slurm" --snakefile "$src/workflow/Snakefile" \
     --max-status-checks-per-second 1 --config sweep="$work/mini.toml" out="$work/out" hmlattice="$hm" "$@")
}
sweep_start=$SECONDS
rc=0
smk > "$work/snakemake.log" 2>&1 || rc=$?
[ $rc -eq 0 ] || { tail -n 40 "$work/snakemake.log"; squeue; fail "snakemake with the Slurm profile: exit $rc (137: stopped after 300 s)"; }
echo "slurm-selftest: snakemake --profile workflow/profiles/slurm: $((SECONDS - sweep_start)) s"
smk -n > "$work/dry.log" 2>&1 && grep -q "Nothing to be done" "$work/dry.log" ||
  { cat "$work/dry.log"; fail "a second snakemake still plans jobs"; }

# Every combination: in results.csv, complete with a breakdown pressure, and run by a Slurm job that
# completed with exit code 0 (slurmctld keeps finished jobs for MinJobAge = 300 s; no sacct without
# accounting) and whose output file (.snakemake/slurm_logs/rule_run/<jobid>.log) names that run.
scontrol show job -o > "$work/jobs.txt" || fail "scontrol show job"
/usr/bin/python3 - "$work" "$tmp/slurmctld.log" <<'PY' || fail "checks above"
import csv, math, re, sys
work, ctld_log = sys.argv[1], open(sys.argv[2]).read()
names = [r["name"] for r in csv.DictReader(open(f"{work}/out/mini/cases/index.csv"))]
rows = {r["name"]: r for r in csv.DictReader(open(f"{work}/out/mini/results.csv"))}
jobs = [dict(re.findall(r"(\S+?)=(\S*)", line)) for line in open(f"{work}/jobs.txt")]
runs = [j for j in jobs if j["JobName"].startswith("snakejob_run_")]
ok = len(names) == 4 and len(runs) == len(names)
print(f"slurm-selftest: {len(names)} combinations, {len(runs)} Slurm jobs of rule run")
for name in names:
    r = rows.get(name, {})
    done = r.get("status") == "complete" and not math.isnan(float(r.get("p_h_first_break", "nan")))
    job = [j for j in runs if f"/runs/{name}\n" in open(j["StdOut"]).read()]
    j = job[0] if len(job) == 1 else {}
    slurm = (j.get("JobState") == "COMPLETED" and j.get("ExitCode") == "0:0"
             and f"_job_complete: JobId={j['JobId']} WEXITSTATUS 0" in ctld_log)
    ok &= done and slurm
    print(f"  {name:14} {'ok  ' if done and slurm else 'FAIL'} Slurm job {j.get('JobId', '-')} "
          f"{j.get('JobState', 'none')} exit {j.get('ExitCode', '-')} mem {j.get('MinMemoryNode', '-')} "
          f"limit {j.get('TimeLimit', '-')} node {j.get('NodeList', '-')}; results.csv: "
          f"{r.get('status', 'missing')}, p_h at first break {r.get('p_h_first_break', '-')}")
sys.exit(0 if ok else 1)
PY
echo "slurm-selftest: PASS (4 runs as Slurm jobs, results.csv complete, nothing left to do; $((SECONDS - start)) s)"
