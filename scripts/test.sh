#!/usr/bin/env bash
# The whole test suite: release build (C model, RTL co-simulation, benchmarks), the
# AddressSanitizer + UBSan build of the C-model tests, and the fuzz targets' short run
# (scripts/fuzz.sh: corpora replayed, each target fuzzed for seconds; docs/robustness.md).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
jobs=$(nproc)
cmake --preset default >/dev/null
cmake --build --preset default -j "$jobs"
ctest --preset default -j "$jobs"
cmake --preset asan >/dev/null
cmake --build --preset asan -j "$jobs"
ctest --preset asan -j "$jobs"
scripts/fuzz.sh
