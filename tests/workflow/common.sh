# The start of every workflow test, sourced with the test's arguments <hmlattice executable> <source
# folder>: sets hm and src, exits 77 (skipped) when snakemake is missing, makes the temporary folder
# $work (removed on exit) and defines fail.
set -euo pipefail
hm=$1
src=$2
command -v snakemake >/dev/null || { echo "snakemake not found: skipped (scripts/test.sh installs it)"; exit 77; }

work=$(mktemp -d "${TMPDIR:-/tmp}/hmlattice-workflow-XXXXXX")
trap 'rm -rf "$work"' EXIT
fail() { echo "FAILED: $*" >&2; exit 1; }
