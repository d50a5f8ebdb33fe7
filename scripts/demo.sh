#!/usr/bin/env bash
# Installs dependencies, builds edyn in Release and runs edyn-demo. Arguments go to the demo.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"

bash scripts/deps.sh
cmake -S . -B build-release -DCMAKE_BUILD_TYPE=Release -DEDYN_BUILD_TESTS=OFF >/dev/null
cmake --build build-release -j "$(nproc)" --target edyn-demo
./build-release/examples/edyn-demo "$@"
