#!/usr/bin/env bash
# Install hmlattice's build and plotting dependencies from Debian 12's archive.
# Idempotent: packages already present are skipped, so a second run does nothing.
# Needs root (or sudo) only when something is missing. Extra Debian packages given as arguments are
# installed the same way (scripts/test.sh adds snakemake for the workflow test; the main job adds none).
set -euo pipefail

packages=(
  g++ cmake make ninja-build pkg-config
  libeigen3-dev libgsl-dev libboost-dev libcgal-dev libsuitesparse-dev
  libtoml11-dev libcli11-dev nlohmann-json3-dev catch2 libbenchmark-dev
  python3-matplotlib python3-numpy python3-meshio python3-pandas python3-pytest
  libopenblas0-pthread  # BLAS/LAPACK behind CHOLMOD's supernodal factorisation: ~1.4-3x faster at N = 1e5
)
packages+=("$@")

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

sudo=""
if [ "$(id -u)" -ne 0 ] && command -v sudo >/dev/null; then sudo=sudo; fi

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
else
  echo "install-deps: installing ${missing[*]}"
  if [ "$(id -u)" -ne 0 ] && [ -z "$sudo" ]; then
    echo "install-deps: not root and no sudo; install: ${missing[*]}" >&2
    exit 1
  fi
  export DEBIAN_FRONTEND=noninteractive
  $sudo apt-get update -qq
  $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
  echo "install-deps: done"
fi

# `import hmlattice` in Debian's python3: a .pth file in /usr/local's site-packages naming this
# checkout's python/ (the last checkout set up wins; `cmake --install` installs a copy instead).
site=$(/usr/bin/python3 -c 'import site; print(site.getsitepackages()[0])')
pth="$site/hmlattice.pth"
here=$(cd "$(dirname "$0")/.." && pwd)/python
if [ "$(cat "$pth" 2>/dev/null)" != "$here" ]; then
  if [ "$(id -u)" -eq 0 ] || [ -n "$sudo" ]; then
    $sudo mkdir -p "$site"
    echo "$here" | $sudo tee "$pth" >/dev/null
    echo "install-deps: import hmlattice now finds $here ($pth)"
  else
    echo "install-deps: not root: for import hmlattice, set PYTHONPATH=$here" >&2
  fi
fi
