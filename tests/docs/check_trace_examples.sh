#!/usr/bin/env bash
# The "check your own code" examples of docs/study-modes.md (docs/examples/liang_barsky_trace.*)
# print traces that `cgsandbox check liang-barsky` accepts, and a one-character slip in one is
# found at its step. The C++ one is built by CMake; the Python one runs when python3 exists.
# Usage: tests/docs/check_trace_examples.sh SOURCE_DIR CGSANDBOX_BINARY CXX_EXAMPLE_BINARY SCRATCH_DIR
set -uo pipefail
root=$1 bin=$2 cxx=$3 dir=$4
rm -rf "$dir"
mkdir -p "$dir"
fail=0
check() {  # NAME FILE: the trace must agree
  if ! "$bin" check liang-barsky --trace "$2" >"$dir/$1.out" 2>&1; then
    echo "docs/examples: the $1 example's trace does not agree:" >&2
    cat "$dir/$1.out" >&2
    fail=1
  fi
}
"$cxx" >"$dir/cxx.jsonl" && check C++ "$dir/cxx.jsonl"
if command -v python3 >/dev/null; then
  python3 "$root/docs/examples/liang_barsky_trace.py" >"$dir/py.jsonl" && check Python "$dir/py.jsonl"
  # min for max on entering: the checker must stop at the first entering step (step 2).
  sed 's/t_enter = max(t_enter, r)/t_enter = min(t_enter, r)/' \
    "$root/docs/examples/liang_barsky_trace.py" >"$dir/slip.py"
  python3 "$dir/slip.py" >"$dir/slip.jsonl"
  "$bin" check liang-barsky --trace "$dir/slip.jsonl" >"$dir/slip.out" 2>&1
  rc=$?
  if ((rc != 1)) || ! grep -q '^step 2 differs' "$dir/slip.out"; then
    echo "docs/examples: min for max was not caught at step 2 (exit $rc):" >&2
    cat "$dir/slip.out" >&2
    fail=1
  fi
else
  echo "python3 not found: the Python example is not run"
fi
((fail == 0)) && echo "docs/examples: the trace examples agree with cgsandbox check"
exit $fail
