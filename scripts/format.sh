#!/usr/bin/env bash
# Formats every tracked C++ file with the project's .clang-format (clang-format 14 or newer).
# `scripts/format.sh --check` only reports the files that would change and fails if any would.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
formatter=$(command -v clang-format-14 || command -v clang-format || true)
if [[ -z $formatter ]]; then
    echo "format.sh: clang-format is not installed (Debian package clang-format)" >&2
    exit 1
fi
mapfile -t files < <(git ls-files '*.hpp' '*.cpp')
if [[ ${1:-} == --check ]]; then
    "$formatter" --dry-run -Werror "${files[@]}"
else
    "$formatter" -i "${files[@]}"
fi
