#!/usr/bin/env bash
# libFuzzer targets (fuzz/, docs/robustness.md): the scene parser, the vector-file reader and one
# per block (arbitrary in-field codes -> C model, float reference, error metric), all under
# AddressSanitizer + UBSan (preset `fuzz`, clang). A finding is a crash, a sanitizer report or a
# broken invariant; its input is saved as build/fuzz/artifacts/TARGET-*.
#   scripts/fuzz.sh          CI: replay every committed corpus (fuzz/corpus/TARGET), then run each
#                            target for a short time (parsers 6 s, blocks 3 s; nproc at a time)
#   scripts/fuzz.sh --long   >= 10,000,000 runs per parser and 1,000,000 per block
# New inputs go to build/fuzz/corpus/TARGET (not committed); run counts to build/fuzz/logs/.
set -euo pipefail
cd "$(dirname "$0")/.."
mode=${1:-ci}
case $mode in ci|--long) ;; *) echo "usage: scripts/fuzz.sh [--long]" >&2; exit 2 ;; esac
t0=$(date +%s)
# ccache, where installed, makes a rebuild of an unchanged tree cheap (the build is most of the cost).
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake --preset fuzz "${launcher[@]}" >/dev/null
cmake --build --preset fuzz -j "$(nproc)" --target fuzz_all
bin=build/fuzz/fuzz
mkdir -p build/fuzz/logs build/fuzz/artifacts
targets="fuzz_scene fuzz_vectors $(cd $bin && ls -d fuzz_block_*)"  # parsers first
run_one() {
  local t=$1 mode=$2 bin=build/fuzz/fuzz
  local corpus=fuzz/corpus/${t#fuzz_block_}
  [ "$t" = fuzz_scene ] && corpus=fuzz/corpus/scene
  [ "$t" = fuzz_vectors ] && corpus=fuzz/corpus/vectors
  local scratch=build/fuzz/corpus/$t
  mkdir -p "$scratch"
  local limit
  if [ "$mode" = --long ]; then
    case $t in fuzz_scene|fuzz_vectors) limit=-runs=10000000 ;; *) limit=-runs=1000000 ;; esac
  else
    case $t in fuzz_scene|fuzz_vectors) limit=-max_total_time=6 ;; *) limit=-max_total_time=3 ;; esac
  fi
  # -runs=0: replay the committed corpus (every input must pass), then fuzz from it.
  if ! "$bin/$t" -runs=0 "$corpus" >"build/fuzz/logs/$t.replay.log" 2>&1; then
    echo "FINDING: $t on its committed corpus (build/fuzz/logs/$t.replay.log)"; return 1
  fi
  if ! "$bin/$t" $limit -max_len=4096 -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
      -artifact_prefix="build/fuzz/artifacts/$t-" "$scratch" "$corpus" >"build/fuzz/logs/$t.log" 2>&1; then
    echo "FINDING: $t (build/fuzz/logs/$t.log, input in build/fuzz/artifacts/)"; return 1
  fi
  local runs
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "build/fuzz/logs/$t.log")
  printf '%-28s %12s runs, no finding\n' "$t" "$runs"
}
export -f run_one
status=0
printf '%s\n' $targets | xargs -P "$(nproc)" -I{} bash -c 'run_one {} '"$mode" || status=1
echo "fuzz ($mode): $(echo $targets | wc -w) targets, $(( $(date +%s) - t0 )) s including the build"
exit $status
