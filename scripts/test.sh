#!/usr/bin/env bash
# Installs dependencies, builds edyn with its tests and runs them through CTest.
#   scripts/test.sh            normal build (RelWithDebInfo, assertions on, EDYN_AVX2 where the
#                              CPU has AVX2, EDYN_AVX512 where it has AVX-512F and VL) in build/
#   scripts/test.sh --asan     AddressSanitizer + UndefinedBehaviorSanitizer in build-asan/ (the
#                              behaviour suite once, in the sequential mode: its copies in the
#                              threaded modes run the same scenes, and the threaded modes' own
#                              unit tests run under the sanitizers too)
#   scripts/test.sh --tsan     ThreadSanitizer in build-tsan/
#                              (sanitizer builds leave out the benchmarks and the demo)
#   scripts/test.sh --double   edyn::scalar = double in build-double/
#   --only=T1,T2               builds only these test targets (and the library) and runs only
#                              their tests (those labelled T1 or T2), e.g. the threaded tests
#                              under ThreadSanitizer in CI
# Other arguments are passed to ctest (e.g. -R registry, -L edyn-test-math).
# Warnings are errors when CI is set or with --werror. Sanitizer builds, and every build under CI,
# keep line tables only (-g1): stack traces still name file and line, and compiling takes about a
# quarter less time. Sanitizer builds also compile at -O1, which builds 40 % faster than -O2, and
# as unity builds (CMake joins each target's source files eight to a compilation, so that the
# inline functions and templates they share are compiled once per eight files). The test
# programs are unity builds in every build (tests/CMakeLists.txt); the normal build compiles each
# file of the library, the scenes, the benchmarks and the examples alone, so that CI still checks
# that each includes what it uses, and the sanitizer builds check that the library's files can
# be joined (no two of them define the same name in their anonymous namespaces).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"

build_dir=build
cmake_args=(-DCMAKE_BUILD_TYPE=RelWithDebInfo)
ctest_args=()
# Sanitizer builds cover the library and its tests; the benchmarks (with Bullet) and the demo
# are built and smoke-tested by the normal build, which keeps CI within its time limit; so is the
# API reference (docs.reference).
sanitized=(-DEDYN_BUILD_BENCH=OFF -DEDYN_BUILD_EXAMPLES=OFF -DEDYN_BUILD_DOCS=OFF -DEDYN_BUILD_TESTBED=OFF
           "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" -DCMAKE_UNITY_BUILD=ON)
werror=${CI:+ON}
only=()
for arg in "$@"; do
  case "$arg" in
    --asan) build_dir=build-asan; cmake_args+=(-DEDYN_SANITIZE=address "${sanitized[@]}")
            ctest_args+=(-LE '^edyn-test-behaviour-(multithreaded|asynchronous)$') ;;
    --tsan) build_dir=build-tsan; cmake_args+=(-DEDYN_SANITIZE=thread "${sanitized[@]}") ;;
    --double) build_dir=build-double; cmake_args+=(-DEDYN_DOUBLE_PRECISION=ON) ;;
    --werror) werror=ON ;;
    --only=*) IFS=, read -ra only <<<"${arg#--only=}" ;;
    *) ctest_args+=("$arg") ;;
  esac
done
cmake_args+=(-DEDYN_WERROR=${werror:-OFF})
if [[ "$build_dir" != build-asan && "$build_dir" != build-tsan ]]; then
  cmake_args+=("-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 -g${CI:+1} -DNDEBUG")
  # Eight-lane contact bundles where this CPU has AVX2 (scripts/vector_options.sh); the sanitizer
  # builds keep the four-lane path, so that both are tested against the same pinned hashes.
  read -ra vector_options <<<"$(bash scripts/vector_options.sh)"
  cmake_args+=("${vector_options[@]}")
fi

bash scripts/deps.sh
# New build folders use Ninja (an existing folder keeps the generator it was made with).
export CMAKE_GENERATOR=${CMAKE_GENERATOR:-Ninja}
jobs=$(nproc)
cmake -S . -B "$build_dir" "${cmake_args[@]}" >/dev/null
if [ ${#only[@]} -gt 0 ]; then
  cmake --build "$build_dir" -j "$jobs" --target "${only[@]}"
  ctest_args+=(-L "^($(IFS='|'; echo "${only[*]}"))\$")
else
  cmake --build "$build_dir" -j "$jobs"
fi

export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=0}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
export TSAN_OPTIONS=${TSAN_OPTIONS:-halt_on_error=1:second_deadlock_stack=1}
ctest --test-dir "$build_dir" --output-on-failure -j "$jobs" "${ctest_args[@]}"
