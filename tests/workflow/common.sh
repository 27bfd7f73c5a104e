# The start of every workflow test, sourced with the test's arguments <hmlattice executable> <source
# folder>: sets hm and src, exits 77 (skipped) when snakemake is missing, makes the temporary folder
# $work (removed on exit) and defines fail (tests/scratch_folder.sh).
set -euo pipefail
hm=$1
src=$2
command -v snakemake >/dev/null || { echo "snakemake not found: skipped (scripts/test.sh installs it)"; exit 77; }
. "$(dirname "${BASH_SOURCE[0]}")/../scratch_folder.sh" workflow
