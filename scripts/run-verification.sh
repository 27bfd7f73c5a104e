#!/usr/bin/env bash
# The main job: install dependencies, build, run the verification suite, say where the report is.
#   scripts/run-verification.sh                  quick tier (minutes) into out/verify
# An earlier report there is replaced (--overwrite); a folder that hmlattice did not write never is.
#   scripts/run-verification.sh --tier paper     paper resolution
# Extra arguments go to `hmlattice verify`.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh hmlattice  # the program only; the tests are the test command's
./build/hmlattice verify --overwrite "$@"
