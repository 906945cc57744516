#!/usr/bin/env bash
# The documentation reads as a reference for someone who has only this repository:
#  - no history of the work ("session", "issue N") and no path outside the repository ("shared/")
#    in docs/ or README.md;
#  - no block page (docs/blocks/*.md, appendix pages excepted) over 2,500 words, README.md <= 1,000;
#  - every relative link in docs/ and README.md names a file that exists.
# Usage: scripts/docs_check.sh [REPO_ROOT]. Exit 0 clean, 1 with one line per finding.
#        scripts/docs_check.sh --self-test: runs the check on a small tree holding one of each
#        violation and on its clean twin; exit 0 when it reports every one and passes the twin.
set -u
if [ "${1:-}" = --self-test ]; then
  t=$(mktemp -d) && trap 'rm -rf "$t"' EXIT
  mk() {  # mk DIR: a clean tree
    mkdir -p "$1/docs/blocks" "$1/docs/methods"
    printf '# A\n\n[b](../methods/m.md#x), [top](../../README.md), [web](https://example.org/y.md)\n' > "$1/docs/blocks/a.md"
    yes word | head -n 2495 | tr '\n' ' ' >> "$1/docs/blocks/a.md"
    yes word | head -n 3000 | tr '\n' ' ' > "$1/docs/blocks/a-appendix.md"
    printf '# M\n\nthe shared core; `[not](a link.md)`\n' > "$1/docs/methods/m.md"
    printf '# R\n\n[a](docs/blocks/a.md)\n' > "$1/README.md"
  }
  mk "$t/clean"; mk "$t/bad"
  echo 'Session 8 measured it.' >> "$t/bad/docs/methods/m.md"
  echo 'As in issue 41.' >> "$t/bad/README.md"
  echo 'See shared/spec/SPEC.md.' >> "$t/bad/docs/blocks/a-appendix.md"
  echo 'one more word' >> "$t/bad/docs/blocks/a.md"
  echo '[gone](../nowhere.md)' >> "$t/bad/docs/methods/m.md"
  yes word | head -n 1001 | tr '\n' ' ' >> "$t/bad/README.md"
  "$0" "$t/clean" > "$t/clean.log" || { echo "docs_check self-test: the clean tree fails:"; cat "$t/clean.log"; exit 1; }
  "$0" "$t/bad" > "$t/bad.log" && { echo "docs_check self-test: the bad tree passes"; exit 1; }
  for want in 'docs/methods/m.md:4:Session 8' 'README.md:4:As in issue 41' 'a-appendix.md:1: word word word word word See shared/' \
              'docs/blocks/a.md: 2503 words' 'README.md: 10' 'broken link to ../nowhere.md'; do
    grep -qF "$want" "$t/bad.log" || { echo "docs_check self-test: not reported: $want"; cat "$t/bad.log"; exit 1; }
  done
  [ "$(grep -c 'docs_check:' "$t/bad.log")" -eq 6 ] || { echo "docs_check self-test: extra findings:"; cat "$t/bad.log"; exit 1; }
  echo "docs_check self-test: ok"; exit 0
fi
root=${1:-$(cd "$(dirname "$0")/.." && pwd)}
cd "$root" || { echo "docs_check: no directory $root" >&2; exit 2; }
fail=0
say() { echo "docs_check: $*"; fail=1; }

mapfile -t pages < <(find docs -name '*.md' | sort; echo README.md)

# 1. History and outside paths.
while IFS= read -r hit; do say "history or outside path: $hit"; done < <(
  grep -HnoiE '.{0,30}(\bsessions?\b|\bissues? #?[0-9]|shared/).{0,30}' "${pages[@]}")

# 2. Word limits.
for f in docs/blocks/*.md; do
  case $f in *-appendix.md) continue ;; esac
  n=$(wc -w < "$f")
  [ "$n" -le 2500 ] || say "$f: $n words (block pages <= 2500; move derivations and logs to its appendix)"
done
n=$(wc -w < README.md)
[ "$n" -le 1000 ] || say "README.md: $n words (<= 1000)"

# 3. Relative links [text](target), anchors and URLs aside; code spans ignored.
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
