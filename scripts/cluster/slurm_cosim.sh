#!/usr/bin/env bash
# Slurm array job: one co-simulation shard per task, merged by the last step (docs/performance.md,
# "Beyond one machine"). Each task generates its own rows of the set (no shared vector file), so
# a node needs only the texunit binary and a shared output directory.
#   sbatch --array=0-63 scripts/cluster/slurm_cosim.sh ewa 4194304 7 /shared/run1
#   (after the array:)  texunit merge /shared/run1/cosim_*.json --json /shared/run1/ewa.json
# Arguments: BLOCK COUNT SEED OUTDIR; TU_TEXUNIT overrides the binary path.
#SBATCH --job-name=texunit-cosim
#SBATCH --cpus-per-task=1
#SBATCH --time=02:00:00
set -euo pipefail
block=$1 count=$2 seed=$3 out=$4
tu=${TU_TEXUNIT:-build/default/tools/texunit/texunit}
k=${SLURM_ARRAY_TASK_ID:?run as an array job (sbatch --array=0-N-1)}
n=${SLURM_ARRAY_TASK_COUNT:?run as an array job (sbatch --array=0-N-1)}
mkdir -p "$out"
vec=$(mktemp "${TMPDIR:-/tmp}/texunit-shard.XXXXXX.vec")
trap 'rm -f "$vec"' EXIT
"$tu" vectors --block "$block" --set random --count "$count" --seed "$seed" --shard "$k/$n" --threads 1 --out "$vec"
# Written under a temporary name and renamed: the merge never reads a half-written shard.
"$tu" cosim --block "$block" --vectors "$vec" --json >"$out/.cosim_$k.json"
mv "$out/.cosim_$k.json" "$out/cosim_$k.json"
