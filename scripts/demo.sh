#!/usr/bin/env bash
# Installs dependencies and builds edyn in Release. With a display, opens edyn-testbed (the
# visual sample browser); without one, runs the text demo edyn-demo and writes screenshots of
# two samples, rendered off-screen under Xvfb, to build-release/demo/. Arguments go to the
# program that runs.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"

bash scripts/deps.sh
# New build folders use Ninja (an existing folder keeps the generator it was made with).
export CMAKE_GENERATOR=${CMAKE_GENERATOR:-Ninja}
# Eight-lane contact bundles where this CPU has AVX2 (scripts/vector_options.sh).
read -ra vector_options <<<"$(bash scripts/vector_options.sh)"
cmake -S . -B build-release -DCMAKE_BUILD_TYPE=Release -DEDYN_BUILD_TESTS=OFF "${vector_options[@]}" >/dev/null
testbed=build-release/testbed/edyn-testbed
if [ -n "${DISPLAY:-}" ]; then
  if cmake --build build-release -j "$(nproc)" --target edyn-testbed; then
    exec "$testbed" "$@"
  fi
  echo "demo.sh: edyn-testbed did not build; running the text demo instead" >&2
fi

cmake --build build-release -j "$(nproc)" --target edyn-demo
./build-release/examples/edyn-demo "$@"

# No display: pictures instead of a window, where the testbed and an X server are available.
if command -v xvfb-run >/dev/null && cmake --build build-release -j "$(nproc)" --target edyn-testbed >/dev/null; then
  mkdir -p build-release/demo
  echo "demo.sh: no display, so the testbed draws its pictures off-screen:"
  for scene in pyramid ragdolls; do
    if xvfb-run -a "$testbed" --scene "$scene" --steps 90 --screenshot "build-release/demo/$scene.png" >/dev/null; then
      echo "  $root/build-release/demo/$scene.png"
    else
      echo "  $scene: xvfb-run or the testbed failed, no picture" >&2
    fi
  done
  echo "  (run scripts/demo.sh on a desktop to open edyn-testbed)"
else
  echo "demo.sh: no display and no xvfb-run or testbed build: no screenshots written"
fi
