# Shared by the CLI test scripts (sourced once tu, src and case are set): a temporary directory
# removed on exit, the source tree as working directory, fail and expect.
tmp=$(mktemp -d)
trap 'chmod -R u+w "$tmp" 2>/dev/null; rm -rf "$tmp"' EXIT
cd "$src"
fail() { echo "FAIL ($case): $*" >&2; exit 1; }
# expect RC PATTERN CMD...: runs CMD, checks its exit code and that stderr matches PATTERN.
expect() {
  local want=$1 pat=$2; shift 2
  set +e
  "$@" >"$tmp/out" 2>"$tmp/err"
  local rc=$?
  set -e
  [ "$rc" = "$want" ] || fail "exit $rc, expected $want: $* ($(head -c 400 "$tmp/err"))"
  grep -q -- "$pat" "$tmp/err" || fail "message of '$*' does not match '$pat': $(head -c 400 "$tmp/err")"
  ! grep -q "filesystem error" "$tmp/err" || fail "raw filesystem_error text: $(cat "$tmp/err")"
}
