#!/usr/bin/env bash
# Installs dependencies, builds edyn-bench in Release (build-release/) and runs the standard
# scenes with edyn and with Bullet, one engine after the other. Writes bench/results/latest.json
# (the records), latest.md (the table, also printed) and latest.png (ms/step against body count).
# Arguments go to edyn-bench, e.g. scripts/bench.sh --scene pile --bodies 1024 4096.
#
#   scripts/bench.sh --scaling [body counts]
# instead runs edyn's piles (of 4,096 and 16,384 bodies unless given) on 1, 2, 4, 8 and 16
# threads (as many of those as the machine has cores), three rounds of every count in turn, and
# writes bench/results/scaling.md (the table, each core's speed on one thread and the speed-up
# that independent work gets on the same thread counts, also printed) and scaling.png (speed-up
# against threads).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"

bash scripts/deps.sh
# New build folders use Ninja (an existing folder keeps the generator it was made with).
export CMAKE_GENERATOR=${CMAKE_GENERATOR:-Ninja}
# Eight-lane contact bundles where this CPU has AVX2 (scripts/vector_options.sh).
read -ra vector_options <<<"$(bash scripts/vector_options.sh)"
cmake -S . -B build-release -DCMAKE_BUILD_TYPE=Release -DEDYN_BUILD_TESTS=OFF "${vector_options[@]}" >/dev/null
cmake --build build-release -j "$(nproc)" --target edyn-bench

results=bench/results
mkdir -p "$results"

if [ "${1:-}" = "--scaling" ]; then
  shift
  piles=("$@")
  [ ${#piles[@]} -gt 0 ] || piles=(4096 16384)
  runs=$(mktemp -d)
  trap 'rm -rf "$runs"' EXIT
  counts=()
  for threads in 1 2 4 8 16; do
    [ "$threads" -le "$(nproc)" ] || break
    counts+=("$threads")
  done
  # Each core's speed on one thread, a short pile pinned to it: a shared machine may lend some
  # cores less time than others, and a parallel step goes at the pace of its slowest thread.
  core_speeds() {
    local cpu out speeds=()
    for ((cpu = 0; cpu < $(nproc) && cpu < 16; cpu++)); do
      out=$(taskset -c "$cpu" ./build-release/bench/edyn-bench --scene pile --bodies 1024 --steps 240 \
        --warmup 120 --engine edyn 2>&1 | grep -o 'median [0-9.]*' | head -1 | cut -d' ' -f2)
      speeds+=("cpu $cpu: ${out:-?} ms")
    done
    (IFS=,; echo "${speeds[*]}" | sed 's/,/, /g')
  }
  before=$(core_speeds)
  # Three rounds, each running every thread count in turn, so that a change in the machine
  # between rounds weighs on every count alike; of each count's three runs the fastest is kept,
  # as edyn-bench --repeat keeps its fastest.
  for round in 1 2 3; do
    for threads in "${counts[@]}"; do
      ./build-release/bench/edyn-bench --scene pile --bodies "${piles[@]}" --engine edyn \
        --threads "$threads" --json "$runs/$threads-$round.json" >/dev/null
    done
  done
  after=$(core_speeds)
  # The machine's own ceiling: what independent work gains on the same thread counts. Logical
  # CPUs that share a core's arithmetic units give the arithmetic kernel little speed-up.
  ceiling=""
  if [ "${counts[-1]}" -ge 2 ]; then
    ceiling=$(./build-release/bench/edyn-bench --machine-ceiling --threads "${counts[-1]}" 2>/dev/null)
  fi
  # "bodies threads median_ms" per run, the fastest of each (bodies, threads), then the speed-up
  # over the same pile on one thread.
  cat "$runs"/*.json | grep '"engine": "edyn"' |
    sed -E 's/.*"bodies": ([0-9]+).*"threads": ([0-9]+).*"median_ms": ([-0-9.e+]+).*/\1 \2 \3/' |
    sort -k1,1n -k2,2n -k3,3g | awk '!seen[$1 " " $2]++' |
    awk '$2 == 1 { one[$1] = $3 } { print $1, $2, $3, one[$1] / $3 }' >"$runs/scaling.dat"
  {
    echo "Pile, edyn-bench, the fastest of 3 runs taken in turns with the other thread counts, on $(nproc) cores ($(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//')), commit $(git rev-parse --short HEAD 2>/dev/null || echo unknown):"
    echo
    echo "| bodies | threads | median ms/step | speed-up over 1 thread |"
    echo "| ---: | ---: | ---: | ---: |"
    awk '{ printf "| %d | %d | %.3f | %.2f |\n", $1, $2, $3, $4 }' "$runs/scaling.dat"
    echo
    echo "Each core on one thread (a 1,024-body pile, median ms per step), before the runs: $before;"
    echo "after them: $after."
    if [ -n "$ceiling" ]; then
      echo
      echo "What independent work gains over one thread on this machine (edyn-bench --machine-ceiling):"
      echo
      echo "$ceiling"
    fi
  } | tee "$results/scaling.md"
  plots=()
  for bodies in "${piles[@]}"; do
    awk -v n="$bodies" '$1 == n { print $2, $4 }' "$runs/scaling.dat" >"$runs/pile-$bodies.dat"
    plots+=("'$runs/pile-$bodies.dat' using 1:2 with linespoints lw 2 pt 7 title 'pile, $bodies bodies'")
  done
  gnuplot -e "out='$results/scaling.png'; cores=$(nproc); piles=\"$(IFS=,; echo "${plots[*]}")\"" bench/scaling.gp
  echo "bench.sh: wrote $results/scaling.md and $results/scaling.png"
  exit 0
fi
{
  echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//')"
  echo "date: $(date -u +%Y-%m-%dT%H:%MZ)"
  echo "commit: $(git rev-parse --short HEAD 2>/dev/null || echo unknown)"
  echo "command: edyn-bench --json $results/latest.json --markdown $results/latest.md $*"
} >"$results/latest.txt"
./build-release/bench/edyn-bench --json "$results/latest.json" --markdown "$results/latest.md" "$@"

# One series file per (scene, engine) for gnuplot: "bodies median_ms p95_ms", by body count.
# The JSON is edyn-bench's own, one record per line.
series=$(mktemp -d)
trap 'rm -rf "$series"' EXIT
for scene in pile pyramid; do
  for engine in edyn bullet; do
    grep "\"scene\": \"$scene\"" "$results/latest.json" | grep "\"engine\": \"$engine\"" |
      sed -E 's/.*"bodies": ([0-9]+).*"median_ms": ([-0-9.e+]+).*"p95_ms": ([-0-9.e+]+).*/\1 \2 \3/' |
      sort -n >"$series/$scene-$engine.dat" || true
  done
done
# The n log n reference goes through edyn's smallest pile.
c=$(awk 'NR == 1 && $1 > 1 { printf "%.9g", $2 / ($1 * log($1)) }' "$series/pile-edyn.dat")
if [ -n "$c" ]; then
  gnuplot -e "dir='$series'; out='$results/latest.png'; c=$c" bench/plot.gp
  echo "bench.sh: wrote $results/latest.json, $results/latest.md and $results/latest.png"
else
  echo "bench.sh: no edyn pile in this run, so no plot; wrote $results/latest.json and $results/latest.md"
fi
