#!/usr/bin/env bash
# Fails when the library holds a fused multiply-add instruction, and names the functions that do.
# A fused multiply-add rounds once where the plain code rounds twice, so the library's results
# would then depend on the build (CMakeLists.txt, EDYN_AVX2 and EDYN_AVX512).
#   no_fused_multiply_add.sh OBJDUMP LIBRARY
set -euo pipefail
objdump=$1
library=$2
found=$("$objdump" -d --no-show-raw-insn -C "$library" |
  awk '/^[0-9a-f]+ <.*>:$/ { function_name = $0; named = 0 }
       /\tvfn?m(add|sub)/ { if (!named) print function_name; named = 1; print "   " $0 }')
if [ -n "$found" ]; then
  echo "fused multiply-add instructions in $library:"
  printf '%s\n' "$found" | head -40 || true
  exit 1
fi
echo "no fused multiply-add in $library"
