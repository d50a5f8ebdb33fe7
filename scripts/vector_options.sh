#!/usr/bin/env bash
# Prints the CMake options for this CPU's vector instructions, for the other scripts: eight-lane
# contact bundles (EDYN_AVX2) where it has AVX2, and with AVX-512's registers (EDYN_AVX512) where
# it also has AVX-512F and AVX-512VL. Every combination gives the same results.
flags=$(grep -m1 '^flags' /proc/cpuinfo 2>/dev/null || true)
has() { [[ " $flags " == *" $1 "* ]]; }
avx2=OFF
avx512=OFF
if has avx2; then
  avx2=ON
  if has avx512f && has avx512vl; then avx512=ON; fi
fi
echo "-DEDYN_AVX2=$avx2 -DEDYN_AVX512=$avx512"
