#!/usr/bin/env bash
# Renders a sample off-screen under Xvfb and checks the picture against the physics.
# Usage: screenshot_test.sh TESTBED CHECKER SAMPLE OUTPUT.png
# Exits 77 (skipped) when no X server can be started here.
set -uo pipefail
testbed=$1 checker=$2 sample=$3 output=$4
steps=${STEPS:-45}

source "$(dirname "$0")/xvfb_available.sh"
rm -f "$output"
xvfb-run -a "$testbed" --scene "$sample" --steps "$steps" --screenshot "$output" || exit 1
"$checker" --scene "$sample" --steps "$steps" --image "$output"
