#!/usr/bin/env bash
# The tests: install dependencies, build, run the unit tests and the quick verification tier.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
ctest --test-dir build --output-on-failure -j "$(nproc)"
