#!/usr/bin/env bash
# The example lesson of docs/lessons.md (the JSON block after the "example-lesson" marker) is a
# valid lesson: `cgsandbox lessons --check` on a folder holding only it lists it and exits 0.
# Usage: tests/docs/check_lesson_example.sh SOURCE_DIR CGSANDBOX_BINARY SCRATCH_DIR
set -uo pipefail
root=$1 bin=$2 dir=$3
rm -rf "$dir"
mkdir -p "$dir"
awk '/<!-- example-lesson/ { found = 1; next }
     found && /^```/ { if (inside) exit; inside = 1; next }
     inside' "$root/docs/lessons.md" >"$dir/example.json"
id=$(sed -n 's/^  "id": "\(.*\)",$/\1/p' "$dir/example.json")
if [[ -z "$id" ]]; then
  echo "docs/lessons.md: no example lesson (a JSON block after <!-- example-lesson -->)" >&2
  exit 1
fi
out=$(CGSANDBOX_LESSONS="$dir" "$bin" lessons --check 2>"$dir/stderr")
rc=$?
if ((rc != 0)) || [[ -s "$dir/stderr" ]] || [[ "$out" != "$id"$'\t'* ]]; then
  cat "$dir/stderr" >&2
  echo "docs/lessons.md: the example lesson \"$id\" does not load (exit $rc): $out" >&2
  exit 1
fi
echo "docs/lessons.md: the example lesson loads: $out"
