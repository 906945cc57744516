#!/usr/bin/env bash
# N co-simulation shards of one random set through GNU parallel (Debian `parallel`), locally or
# across hosts (`--sshlogin host1,host2` with the same checkout and build on each host), then
# `texunit merge` (docs/performance.md, "Beyond one machine").
# Usage: scripts/cluster/parallel_cosim.sh BLOCK COUNT SEED N OUTDIR [extra GNU parallel options...]
#   scripts/cluster/parallel_cosim.sh ewa 4194304 7 16 build/run1 --jobs 2
set -euo pipefail
block=$1 count=$2 seed=$3 n=$4 out=$5
shift 5
tu=$(realpath "${TU_TEXUNIT:-build/default/tools/texunit/texunit}")
mkdir -p "$out"
out=$(realpath "$out")
seq 0 $((n - 1)) | parallel "$@" \
  "$tu vectors --block $block --set random --count $count --seed $seed --shard {}/$n --threads 1 --out $out/v{}.vec 2>/dev/null &&
   $tu cosim --block $block --vectors $out/v{}.vec --json > $out/cosim_{}.json; rc=\$?; rm -f $out/v{}.vec; exit \$rc" || true
# Mismatching shards exit 1 but still write their JSON: the merge reports them.
"$tu" merge "$out"/cosim_*.json --json "$out/$block.json"
