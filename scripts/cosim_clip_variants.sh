#!/usr/bin/env bash
# Co-simulates the texture unit with the EWA border weights' other clip volumes (EwaClipVariant 1 =
# mm_p3 Horner, 2 = mm_p3 Estrin): two more full-unit Verilator models, built only here (not in CI:
# each costs minutes of compile), then TextureUnitRtl.ClipVariantsEqualCModel (every pixel = C model
# with 30 % stalls, cycles = predicted). Usage: scripts/cosim_clip_variants.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
dir=${1:-build/clipvar}
cmake -S . -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=Release -DTU_COSIM_CLIP_VARIANTS=ON -DTU_BENCH=OFF \
  ${CMAKE_CXX_COMPILER_LAUNCHER:+-DCMAKE_CXX_COMPILER_LAUNCHER=$CMAKE_CXX_COMPILER_LAUNCHER} >/dev/null
cmake --build "$dir" --target tu_cosim_tests
"$dir"/testbench/cosim/tu_cosim_tests --gtest_filter='TextureUnitRtl.ClipVariantsEqualCModel:TextureUnitRtl.BorderWeightsEqualCModelWithCyclesPredicted'
