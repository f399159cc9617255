#!/usr/bin/env bash
# `make screenshots` still works: scripts/screenshots.sh, run against the built cgsandbox into a
# scratch folder, writes every picture under docs/images/ that README.md or docs/ shows, each a
# non-empty PNG. (Not optimised here, to keep the test quick.) The browser build's pictures
# (web-*.png, docs/web.md) are not the desktop viewer's: the browser test makes them
# (tests/web/test_web.py --screenshot), so they are left out here.
# Usage: tests/docs/check_screenshots.sh SOURCE_DIR CGSANDBOX_BINARY SCRATCH_DIR
set -uo pipefail
root=$1 bin=$2 out=$3
rm -rf "$out"
mkdir -p "$out"

if ! CG_SCREENSHOTS_OPTIMISE=0 "$root/scripts/screenshots.sh" "$bin" "$out" >"$out/log" 2>&1; then
  cat "$out/log" >&2
  echo "scripts/screenshots.sh failed" >&2
  exit 1
fi

shown=$(cd "$root" && grep -ohE 'images/[A-Za-z0-9._-]+\.png' README.md $(find docs -name '*.md') |
  sed 's|^images/||' | grep -v '^web-' | sort -u)
if [[ -z "$shown" ]]; then
  echo "README.md and docs/ show no picture from docs/images/" >&2
  exit 1
fi
failures=0
for name in $shown; do
  if [[ ! -s "$out/$name" ]]; then
    echo "scripts/screenshots.sh did not make $name, which the documentation shows" >&2
    failures=$((failures + 1))
  elif [[ $(head -c 8 "$out/$name" | od -An -tx1 | tr -d ' \n') != 89504e470d0a1a0a ]]; then
    echo "$name is not a PNG file" >&2
    failures=$((failures + 1))
  fi
done
((failures == 0)) || exit 1
echo "scripts/screenshots.sh made all $(wc -w <<<"$shown") pictures the documentation shows"
