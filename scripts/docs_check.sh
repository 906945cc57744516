#!/usr/bin/env bash
# The documentation reads as a reference for someone who has only this repository:
#  - no history of the work ("session N", "issue N") and no path outside the repository ("shared/")
#    in docs/ or README.md;
#  - no block page (docs/blocks/*.md, appendix pages excepted) over 2,500 words, README.md <= 1,000;
#  - every relative link in docs/ and README.md names a file that exists.
# Usage: scripts/docs_check.sh [REPO_ROOT]. Exit 0 clean, 1 with one line per finding.
set -u
root=${1:-$(cd "$(dirname "$0")/.." && pwd)}
cd "$root" || { echo "docs_check: no directory $root" >&2; exit 2; }
fail=0
say() { echo "docs_check: $*"; fail=1; }

mapfile -t pages < <(find docs -name '*.md' | sort; echo README.md)

# 1. History and outside paths.
while IFS= read -r hit; do say "history or outside path: $hit"; done < <(
  grep -HnoiE '.{0,30}(\bsessions? [0-9]|\bissues? #?[0-9]|shared/).{0,30}' "${pages[@]}")

# 2. Word limits.
for f in docs/blocks/*.md; do
  case $f in *-appendix.md) continue ;; esac
  n=$(wc -w < "$f")
  [ "$n" -le 2500 ] || say "$f: $n words (block pages <= 2500; move derivations and logs to its appendix)"
done
n=$(wc -w < README.md)
[ "$n" -le 1000 ] || say "README.md: $n words (<= 1000)"

# 3. Relative links: [text](target) and [text]: target, anchors and URLs aside; code spans ignored.
for f in "${pages[@]}"; do
  dir=$(dirname "$f")
  while IFS= read -r target; do
    target=${target%%#*}
    [ -n "$target" ] || continue
    case $target in http://*|https://*|mailto:*) continue ;; esac
    [ -e "$dir/$target" ] || say "$f: broken link to $target"
  done < <(sed -e 's/`[^`]*`//g' "$f" | grep -oE '\]\([^) ]+\)' | sed -E 's/^\]\(//; s/\)$//')
done

[ "$fail" -eq 0 ] && echo "docs_check: ok (${#pages[@]} pages)"
exit "$fail"
