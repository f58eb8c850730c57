#!/usr/bin/env bash
# Installs the Debian 12 packages ibms needs that are not yet on this machine (run as root).
# Usage: scripts/install-deps.sh [--report | --checkers | --cluster]
#   --report adds LaTeX for the PDF report and Snakemake for the main job (scripts/run-main.sh);
#   --checkers adds valgrind and Debian's clang with libFuzzer (scripts/run-sanitizers.sh,
#   scripts/run-fuzz.sh); --cluster adds Snakemake, Slurm and MUNGE for the single-node Slurm
#   test (scripts/run-cluster-test.sh)
set -euo pipefail
packages=(build-essential cmake pkg-config git
          libeigen3-dev libgsl-dev libboost-test-dev libhdf5-dev libfftw3-dev
          libtomlplusplus-dev libcli11-dev libfmt-dev numdiff
          python3 python3-matplotlib python3-numpy python3-h5py)
if [[ "${1:-}" == "--checkers" ]]; then
  packages+=(valgrind clang-14 libclang-rt-14-dev)
fi
if [[ "${1:-}" == "--report" ]]; then
  packages+=(latexmk texlive-latex-base texlive-latex-recommended texlive-latex-extra
             texlive-fonts-recommended lmodern snakemake)
fi
if [[ "${1:-}" == "--cluster" ]]; then
  packages+=(snakemake slurm-wlm munge)
fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]} == 0)); then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi
echo "install-deps: installing ${missing[*]}"
SUDO=""
if [[ $(id -u) -ne 0 ]]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
