#!/usr/bin/env bash
# Plays a mouse script in the testbed off-screen under Xvfb, in an execution mode, and checks
# what it did against the physics: the cursor ray on the pyramid's top box, grabbing that box and
# dragging it 160 pixels to the side, and a ball shot at the bottom row.
# Usage: interaction_test.sh TESTBED CHECKER MODE OUTPUT.png
# Exits 77 (skipped) when no X server can be started here.
set -uo pipefail
testbed=$1 checker=$2 mode=$3 output=$4
steps=45
source "$(dirname "$0")/xvfb_available.sh"

targets=$("$checker" --scene pyramid --steps "$steps" --print-targets) || exit 1
read -r tx ty bx by <<<"$targets"
script="ray $tx $ty; press $tx $ty; move $((tx + 160)) $ty 30; wait 90; shoot $bx $by; wait 120"
echo "script: $script"
log="${output%.png}.log"
rm -f "$output" "$log"
xvfb-run -a "$testbed" --scene pyramid --mode "$mode" --steps "$steps" --script "$script" \
  --screenshot "$output" >"$log" || { cat "$log"; exit 1; }
cat "$log"
"$checker" --scene pyramid --steps "$steps" --image "$output" --script "$script" --log "$log"
