#!/usr/bin/env bash
# Bad input gets a message and a non-zero exit, never a crash: an unknown sample (the list of
# samples is printed), an unknown flag (the usage), a window asked for without a display, and
# mouse scripts that are wrong (the message names the command).
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
for script in "jump 1 2" "press 10" "press 10 20 30" "move 10 20 0" "wait -1" "press 9999 10" \
              "ray nan 3" "wait 20000" "shoot 5 5; release x"; do
  out=$("$testbed" --scene pyramid --screenshot /dev/null --script "$script" 2>&1); rc=$?
  [ "$rc" -eq 2 ] || fail "script '$script' exited $rc: $out"
  grep -q "script command" <<<"$out" || fail "script '$script' gave no clear message: $out"
done
out=$("$testbed" --scene pyramid --script "wait 1" 2>&1); rc=$?
[ "$rc" -eq 2 ] && grep -q "needs --screenshot" <<<"$out" || fail "script without --screenshot: $rc $out"
echo ok
