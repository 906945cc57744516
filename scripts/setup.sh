#!/usr/bin/env bash
# Installs the Debian packages texunit needs, only those missing. Idempotent; fast when all present.
set -euo pipefail
PKGS=(cmake ninja-build g++ python3 pkg-config zlib1g-dev verilator libsystemc-dev libglm-dev
      googletest libgtest-dev libbenchmark-dev nlohmann-json3-dev libcli11-dev libpng-dev libstb-dev
      yosys sollya gnuplot clang libfuzzer-14-dev opensta qflow-tech-osu018 iverilog)
missing=()
for p in "${PKGS[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi
if [ "$(id -u)" -ne 0 ]; then
  echo "texunit: missing Debian packages: ${missing[*]}" >&2
  echo "install them with: sudo apt-get install ${missing[*]}" >&2
  exit 1
fi
echo "texunit: installing ${missing[*]}" >&2
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
