#!/usr/bin/env bash
# scripts/apt-install.sh against stand-ins for apt-get, dpkg and sudo on
# PATH: it waits while apt's lock is held (then installs only what is
# missing), fails at once on any other apt-get failure, and gives up on a
# lock held past GAB_APT_WAIT with apt-get's own error.
# Usage: apt_install_test.sh SOURCE_DIR
set -euo pipefail
script="$1/scripts/apt-install.sh"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/bin"

# dpkg -s NAME: installed unless NAME starts with "missing-".
cat >"$work/bin/dpkg" <<'STUB'
#!/usr/bin/env bash
case "$2" in missing-*) exit 1 ;; *) exit 0 ;; esac
STUB
cat >"$work/bin/sudo" <<'STUB'
#!/usr/bin/env bash
exec "$@"
STUB
# apt-get: logs its arguments; the first $LOCKED_CALLS calls fail as a held
# lock does, or every call fails as $FAIL_WITH says.
cat >"$work/bin/apt-get" <<'STUB'
#!/usr/bin/env bash
n=$(( $(cat "$WORK/calls" 2>/dev/null || echo 0) + 1 ))
echo "$n" >"$WORK/calls"
echo "$*" >>"$WORK/log"
if [ -n "${FAIL_WITH:-}" ]; then echo "E: $FAIL_WITH" >&2; exit 100; fi
if [ "$n" -le "${LOCKED_CALLS:-0}" ]; then
  echo "E: Could not get lock /var/lib/apt/lists/lock. It is held by process 4859 (apt-get)" >&2
  exit 100
fi
exit 0
STUB
chmod +x "$work/bin/"*
export WORK="$work" PATH="$work/bin:$PATH" GAB_APT_RETRY_SECONDS=0.1
fail() { echo "FAIL: $*" >&2; exit 1; }
reset() { rm -f "$work/calls" "$work/log"; }

# 1. The lock is held for two calls: the script waits, says so once, then
#    updates and installs the missing packages only.
reset
out="$(LOCKED_CALLS=2 bash "$script" present missing-a missing-b 2>&1)" || fail "a held lock was not waited for: $out"
[ "$(grep -c 'another process holds apt' <<<"$out")" -eq 1 ] || fail "the wait is not said once: $out"
[ "$(sed -n 3p "$work/log")" = "update" ] || fail "update not retried: $(cat "$work/log")"
[ "$(sed -n 4p "$work/log")" = "install -y --no-install-recommends missing-a missing-b" ] ||
  fail "install line: $(cat "$work/log")"

# 2. Nothing missing: apt-get is not run at all (GAB_APT_UPDATE=always: update only).
reset
bash "$script" present other >/dev/null 2>&1 || fail "nothing missing failed"
[ ! -f "$work/log" ] || fail "apt-get ran with nothing missing: $(cat "$work/log")"
GAB_APT_UPDATE=always bash "$script" present >/dev/null 2>&1 || fail "GAB_APT_UPDATE=always failed"
[ "$(cat "$work/log")" = "update" ] || fail "GAB_APT_UPDATE=always ran: $(cat "$work/log")"

# 3. Another failure is not waited for: one call, apt-get's message and code.
reset
status=0
out="$(FAIL_WITH="Unable to locate package missing-x" bash "$script" missing-x 2>&1)" || status=$?
[ "$status" -eq 100 ] || fail "exit $status for a failed apt-get"
grep -qF "Unable to locate package missing-x" <<<"$out" || fail "apt-get's message lost: $out"
[ "$(cat "$work/calls")" -eq 1 ] || fail "a failure that is not the lock was retried"

# 4. A lock held past GAB_APT_WAIT: apt-get's lock error, exit 100.
reset
status=0
out="$(LOCKED_CALLS=1000 GAB_APT_WAIT=1 bash "$script" missing-y 2>&1)" || status=$?
[ "$status" -eq 100 ] || fail "exit $status for a lock held past the wait"
grep -qF "Could not get lock" <<<"$out" || fail "the lock's error is not shown: $out"

# 5. A malformed wait is a usage error.
status=0
GAB_APT_WAIT=soon bash "$script" missing-z >/dev/null 2>&1 || status=$?
[ "$status" -eq 2 ] || fail "GAB_APT_WAIT=soon gave exit $status"
echo "apt-install.sh: all cases pass"
