#!/usr/bin/env bash
# Keeps the guide in step with the programs it shows. In docs/guide/*.md:
#   <!-- example: examples/friction/main.cpp -->   the next fenced block must be that file, whole;
#   <!-- output: friction -->                       the next fenced block must be what
#                                                   edyn-example-friction prints (checked only
#                                                   with --outputs DIR, DIR holding the programs).
# Every examples/<topic>/main.cpp but the demo's must be shown on some page.
# Usage: docs/guide/check_guide.sh [--outputs BUILD/examples]   (from the repository root)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/../.."

outputs=""
if [[ $# -eq 2 && $1 == --outputs ]]; then
    outputs=$2
elif [[ $# -ne 0 ]]; then
    echo "usage: docs/guide/check_guide.sh [--outputs BUILD/examples]" >&2
    exit 2
fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# Writes each marked block to $work/<n> and lists "n kind target page line" in $work/index.
for page in docs/guide/*.md; do
    awk -v dir="$work" -v page="$page" '
        /^<!-- (example|output): [^ ]+ -->$/ {
            kind = $2; sub(/:$/, "", kind); target = $3; want = 1; at = FNR; next
        }
        want && /^```/ {
            name = dir "/" substr(page, length("docs/guide/") + 1) "." (++n)
            printf "" > name
            print name, kind, target, page, at >> (dir "/index")
            inside = 1; want = 0; next
        }
        want && !/^[[:space:]]*$/ {
            print page ":" at ": marker not followed by a fenced block" > "/dev/stderr"
            bad = 1; want = 0
        }
        inside && /^```$/ { inside = 0; close(name); next }
        inside { print >> name }
        END { if (want) { print page ":" at ": marker at the end of the page" > "/dev/stderr"; bad = 1 }
              exit bad }
    ' "$page"
done
touch "$work/index"

status=0
checked=0
while read -r block kind target page line; do
    if [[ $kind == example ]]; then
        if [[ ! -f $target ]]; then
            echo "$page:$line: $target does not exist" >&2
            status=1
        elif ! diff -u "$target" "$block" >"$work/diff"; then
            echo "$page:$line: the block differs from $target (- file, + page):" >&2
            cat "$work/diff" >&2
            status=1
        fi
        checked=$((checked + 1))
    elif [[ -n $outputs ]]; then
        program="$outputs/edyn-example-$target"
        if [[ ! -x $program ]]; then
            echo "$page:$line: $program is not built" >&2
            status=1
        elif ! "$program" >"$work/out" 2>&1 || ! diff -u "$work/out" "$block" >"$work/diff"; then
            echo "$page:$line: the output shown differs from what $program prints (- program, + page):" >&2
            cat "$work/diff" >&2
            status=1
        fi
        checked=$((checked + 1))
    fi
done <"$work/index"

for file in examples/*/main.cpp; do
    [[ $file == examples/demo/main.cpp ]] && continue
    if ! grep -q "^[^ ]* example $file " "$work/index"; then
        echo "docs/guide: no page shows $file" >&2
        status=1
    fi
done

if [[ $status -eq 0 ]]; then
    echo "docs/guide: $checked blocks match their programs"
fi
exit $status
