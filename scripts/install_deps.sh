#!/usr/bin/env bash
# Installs the Debian packages ddcontact needs, and nothing when all are
# present. Non-interactive; needs root (or sudo) only when something is missing.
set -euo pipefail

packages=(libdeal.ii-dev gmsh cmake ninja-build g++ make)
# lld links the Debug test programs in less than half the time of gold.
packages+=(lld)
# summary.json is written (and read by the tests) with nlohmann JSON.
packages+=(nlohmann-json3-dev)
# MPI launcher for the distributed runs and their tests.
packages+=(openmpi-bin)
# The plots of doc/ (scripts/*.py).
packages+=(python3-matplotlib)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

echo "ddcontact: installing missing packages: ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
