#!/usr/bin/env bash
# Install hmlattice's build and plotting dependencies from Debian 12's archive.
# Idempotent: packages already present are skipped, so a second run does nothing.
# Needs root (or sudo) only when something is missing. Extra Debian packages given as arguments are
# installed the same way (scripts/test.sh adds snakemake for the workflow test; the main job adds none).
set -euo pipefail

packages=(
  g++ cmake make pkg-config
  libeigen3-dev libgsl-dev libboost-dev libcgal-dev libsuitesparse-dev
  libtoml11-dev libcli11-dev nlohmann-json3-dev catch2 libbenchmark-dev
  python3-matplotlib python3-numpy python3-meshio
  libopenblas0-pthread  # BLAS/LAPACK behind CHOLMOD's supernodal factorisation: ~1.4-3x faster at N = 1e5
)
packages+=("$@")

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
sudo=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "install-deps: not root and no sudo; install: ${missing[*]}" >&2; exit 1; }
  sudo=sudo
fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "install-deps: done"
