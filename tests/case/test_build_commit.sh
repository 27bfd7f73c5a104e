#!/usr/bin/env bash
# The program names the commit it was built from, also after an incremental build of a tree that was
# configured at an earlier commit (results recorded the configure-time commit), and marks a build of
# a tree with uncommitted changes as such.
#   test_build_commit.sh <hmlattice> <source dir>
set -euo pipefail
program=$1 source=$2
if ! expected=$(git -C "$source" rev-parse --short=12 HEAD 2>/dev/null); then
  echo "not a git checkout: the program says 'unknown'"
  expected=unknown
elif ! git -C "$source" diff --quiet HEAD --; then
  expected="$expected-modified"
fi
actual=$("$program" --version)
if [[ "$actual" != *"(commit $expected, "* ]]; then
  echo "hmlattice --version says '$actual'; the source is at $expected (rebuild?)"
  exit 1
fi
echo "build commit: passed ($actual)"
