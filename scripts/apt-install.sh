#!/usr/bin/env bash
# Installs the Debian packages named on the command line that are missing
# (apt-get update first, then apt-get install --no-install-recommends), and
# waits while another process holds apt's or dpkg's lock (a fresh machine's
# unattended upgrade, another terminal) instead of failing at once:
# apt-get gives up on a held lock with exit 100 and "Could not get lock".
# The wait is bounded: GAB_APT_WAIT seconds in all (default 600), then the
# lock's error is the script's. GAB_APT_UPDATE=always runs apt-get update
# even when nothing is missing (CI: the package lists may be stale).
set -euo pipefail

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
wait_limit="${GAB_APT_WAIT:-600}"
case "$wait_limit" in
  '' | *[!0-9]*) echo "apt-install.sh: GAB_APT_WAIT must be a number of seconds, got '$wait_limit'" >&2; exit 2 ;;
esac
deadline=$((SECONDS + wait_limit))

# apt-get "$@", retried while the failure is a held lock and the deadline is
# ahead. Its stderr is kept to tell a held lock from any other failure (a
# missing package must fail at once, not after the wait).
apt_get() {
  local err status said=""
  err="$(mktemp)"
  while :; do
    status=0
    $SUDO env DEBIAN_FRONTEND=noninteractive apt-get "$@" 2>"$err" || status=$?
    if [ "$status" -eq 0 ]; then cat "$err" >&2; rm -f "$err"; return 0; fi
    if grep -qE 'Could not get lock|Unable to lock|Unable to acquire' "$err" && [ "$SECONDS" -lt "$deadline" ]; then
      if [ -z "$said" ]; then
        echo "apt-install.sh: another process holds apt's lock; waiting (at most ${wait_limit} s in all, GAB_APT_WAIT)" >&2
        said=1
      fi
      sleep "${GAB_APT_RETRY_SECONDS:-5}"
      continue
    fi
    cat "$err" >&2
    rm -f "$err"
    return "$status"
  done
}

missing=()
for p in "$@"; do
  dpkg -s "$p" >/dev/null 2>&1 || missing+=("$p")
done
if [ "${#missing[@]}" -eq 0 ] && [ "${GAB_APT_UPDATE:-}" != always ]; then exit 0; fi
if [ "${#missing[@]}" -gt 0 ]; then echo "installing: ${missing[*]}" >&2; fi
apt_get update
if [ "${#missing[@]}" -gt 0 ]; then
  apt_get install -y --no-install-recommends "${missing[@]}"
fi
