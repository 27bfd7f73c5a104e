#!/usr/bin/env bash
# Configure and build (Release) into build/: every target, or only those named (run-verification.sh
# builds just the program). Called by run-verification.sh and test.sh.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release > build-configure.log 2>&1 || { cat build-configure.log; exit 1; }
rm -f build-configure.log
cmake --build build -j "$(nproc)" ${1:+--target "$@"}
