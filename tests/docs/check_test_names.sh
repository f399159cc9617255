#!/usr/bin/env bash
# Test names that CTest can run: catch_discover_tests hands each TEST_CASE's name to CTest,
# which splits a name at ';' into two tests that both fail (three names did, in one session).
# Fails listing every TEST_CASE whose name (its first string literal, maybe on the next line)
# contains a ';'.
# Usage: tests/docs/check_test_names.sh [SOURCE_DIR]
set -uo pipefail
export LC_ALL=C.UTF-8
root=${1:-$(cd "$(dirname "$0")/../.." && pwd)}
cd "$root" || exit 2
bad=$(grep -rlZ --include='*.cpp' 'TEST_CASE' tests | xargs -0 grep -Pzo 'TEST_CASE\(\s*"[^"]*;[^"]*"' | tr '\0' '\n')
if [ -n "$bad" ]; then
  echo "test names with ';' (CTest would split them):" >&2
  echo "$bad" >&2
  exit 1
fi
count=$(grep -rho --include='*.cpp' 'TEST_CASE(' tests | wc -l)
echo "$count test cases, none with ';' in its name"
