#!/usr/bin/env bash
# Runs a Google Benchmark binary with repetitions in random interleaved order and prints, per
# benchmark, the smallest CPU time over the repetitions (the least disturbed by other work on a
# shared machine) and its ratio to a reference benchmark of the same run (docs/performance.md).
# Usage: scripts/bench_min.sh REFERENCE BINARY [BENCHMARK OPTIONS...]
#   e.g. scripts/bench_min.sh BM_FloatAnalytic build/default/testbench/bench/tu_ellipse_bench --benchmark_min_time=0.3
set -euo pipefail
[ $# -ge 2 ] || { echo "usage: $0 REFERENCE BINARY [OPTIONS...]" >&2; exit 2; }
ref=$1; bin=$2; shift 2
"$bin" --benchmark_repetitions="${REPS:-7}" --benchmark_enable_random_interleaving=true \
  --benchmark_report_aggregates_only=false --benchmark_format=csv "$@" 2>/dev/null |
  awk -F, -v ref="$ref" '
    /^"BM_/ { n = $1; gsub(/"/, "", n); if (n ~ /_(mean|median|stddev|cv)$/) next
              if (!(n in m) || $4 + 0 < m[n]) { m[n] = $4 + 0; u[n] = $5 }
              if (!(n in seen)) { seen[n] = 1; order[++k] = n } }
    END { for (i = 1; i <= k; ++i) if (order[i] == ref || index(order[i], ref "/") == 1) r = m[order[i]]
          printf "%-48s %14s %10s\n", "benchmark", "min CPU", "/ " ref
          for (i = 1; i <= k; ++i) { n = order[i]
            printf "%-48s %11.4g %-2s %10s\n", n, m[n], u[n], (r > 0 ? sprintf("%.2f", m[n] / r) : "-") } }'
