#!/usr/bin/env bash
# Installs the Debian packages demcal needs (only those missing). Run as root on Debian 12.
set -euo pipefail
packages=(g++ cmake ninja-build pkg-config libeigen3-dev libtbb-dev libnlopt-cxx-dev libceres-dev
          libcli11-dev catch2 nlohmann-json3-dev gnuplot-nox
          chromium  # chromium: headless browser test of the HTML reports (html_report.browser)
          liggghts  # liggghts: exported decks run in LIGGGHTS-PUBLIC 3.8 (export.liggghts_runs)
          libopenmpi-dev openmpi-bin  # the MPI farm of demcal calibrate (DEMCAL_MPI, docs/scale.md)
          python3)  # python3: docs.links and the checkpoint corpus (tests/bad_inputs/ckpt_edit.py)
# scripts/fuzz.sh and scripts/sanitize.sh: clang with libFuzzer and the sanitizer runtimes.
if [[ "${1:-}" == "--fuzz" ]]; then packages+=(clang-14 libclang-rt-14-dev); fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "installing: ${missing[*]}" >&2
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
