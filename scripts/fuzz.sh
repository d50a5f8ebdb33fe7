#!/usr/bin/env bash
# Fuzzes edyn's decoders of network bytes (fuzz/) with libFuzzer under AddressSanitizer and
# UndefinedBehaviorSanitizer.
#   scripts/fuzz.sh [SECONDS]   fuzz for SECONDS (default 60) on up to 2 processes
# Builds with clang++ into build-fuzz/ (the fuzz targets are not part of the main, g++, build),
# seeds build-fuzz/corpus/ with a valid encoding of every packet kind, and keeps the corpus
# between runs. Exits non-zero when an input crashes; the input is kept as
# build-fuzz/artifacts/crash-* and can be replayed with `build-fuzz/packet_fuzzer FILE`.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"

seconds=${1:-60}
if ! [[ "$seconds" =~ ^[0-9]+$ ]] || [ "$seconds" -lt 1 ]; then
  echo "usage: scripts/fuzz.sh [SECONDS]" >&2
  exit 2
fi

bash scripts/deps.sh
# New build folders use Ninja (an existing folder keeps the generator it was made with).
export CMAKE_GENERATOR=${CMAKE_GENERATOR:-Ninja}
build=build-fuzz
cmake -S fuzz -B "$build" -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$build" -j "$(nproc)"

corpus="$build/corpus/packet"
artifacts="$build/artifacts"
log="$build/packet_fuzzer.log"
mkdir -p "$corpus" "$artifacts"
"$build/make_seeds" "$corpus"

# Two processes where there are two cores (fork mode shares one corpus between them).
args=(-max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1
      -artifact_prefix="$artifacts/")
if [ "$(nproc)" -ge 2 ]; then
  args+=(-fork=2)
fi

export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
echo "fuzz: packet_fuzzer for ${seconds} s (log: $log)"
status=0
"$build/packet_fuzzer" "${args[@]}" "$corpus" >"$log" 2>&1 || status=$?

# The last progress line: executions, coverage, corpus size.
grep -E '^#[0-9]+' "$log" | tail -n 1 || true
grep -E '^Done [0-9]+ runs|^stat::number_of_executed_units' "$log" | tail -n 1 || true
if [ "$status" -ne 0 ]; then
  tail -n 60 "$log"
  echo "fuzz: packet_fuzzer failed (exit $status); inputs kept in $artifacts:" >&2
  ls -1 "$artifacts" >&2 || true
  exit 1
fi
echo "fuzz: no failure; corpus of $(find "$corpus" -type f | wc -l) inputs"
