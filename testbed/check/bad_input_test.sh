#!/usr/bin/env bash
# Bad input gets a message and a non-zero exit, never a crash: an unknown sample (the list of
# samples is printed), an unknown flag (the usage), and a window asked for without a display.
set -uo pipefail
testbed=$1
fail() { echo "FAILED: $*"; exit 1; }

out=$("$testbed" --scene no_such_sample --screenshot /dev/null 2>&1); rc=$?
[ "$rc" -ne 0 ] || fail "unknown sample exited 0"
[ "$rc" -lt 128 ] || fail "unknown sample crashed ($rc)"
grep -q "pyramid" <<<"$out" || fail "unknown sample did not list the samples: $out"

out=$("$testbed" --no-such-flag 2>&1); rc=$?
[ "$rc" -ne 0 ] && [ "$rc" -lt 128 ] || fail "unknown flag exited $rc"
grep -qi "usage\|--scene" <<<"$out" || fail "unknown flag did not print the usage: $out"

out=$(env -u DISPLAY -u WAYLAND_DISPLAY "$testbed" --scene pyramid 2>&1); rc=$?
[ "$rc" -ne 0 ] && [ "$rc" -lt 128 ] || fail "no display exited $rc"
grep -q "display" <<<"$out" || fail "no display gave no clear message: $out"
echo ok
