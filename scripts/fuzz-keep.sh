#!/usr/bin/env bash
# After a long `make fuzz`: minimises each target's grown corpus (build-sanitize/fuzz/corpus/<t>,
# plus what tests/fuzz/corpus/<t> held) into tests/fuzz/corpus/<t>, keeping only the inputs that
# reach code the seeds do not (libFuzzer's -merge=1 with the seeds counted as covered first), so
# that CTest's 30-second runs start where the long run got to. Prints each target's count.
# At most FUZZ_KEEP inputs (default 60) are kept per target, the first by name (a content hash,
# so an arbitrary but repeatable choice): replaying an accepted input under the oracles is slow
# (fuzz_algorithm_input's 3,363 merged inputs took over five minutes, 300 of them three), and the 30 s runs must
# stay short.
#   scripts/fuzz-keep.sh [TARGET ...]    (default: every target)
set -uo pipefail
cd "$(dirname "$0")/.."
source scripts/fuzz-common.sh
"$build/bin/fuzz_seeds" "$fuzz/seeds" lessons || exit 1
targets=("$@")
(( ${#targets[@]} )) || targets=("${fuzz_targets[@]}")
for t in "${targets[@]}"; do
  seeds=$(fuzz_seeds_of "$t")
  merged=$(mktemp -d)
  # The seeds go in first, so that their coverage counts as had; they are taken out after.
  for f in "$seeds"/*; do [[ -f $f ]] && cp "$f" "$merged/seed-$(basename "$f")"; done
  "$build/bin/$t" -merge=1 -timeout=10 -rss_limit_mb=2048 -max_len=8192 \
    "$merged" "$fuzz/corpus/$t" "tests/fuzz/corpus/$t" >"$fuzz/logs/$t.merge.log" 2>&1 || {
    echo "$t: the merge failed, see $fuzz/logs/$t.merge.log"
    rm -rf "$merged"
    exit 1
  }
  rm -f "$merged"/seed-*
  ls "$merged" | sort | tail -n +$(( ${FUZZ_KEEP:-60} + 1 )) | (cd "$merged" && xargs -r rm -f)
  find "tests/fuzz/corpus/$t" -type f ! -name .gitkeep -delete
  cp "$merged"/* "tests/fuzz/corpus/$t/" 2>/dev/null
  rm -rf "$merged"
  echo "$t: $(find "tests/fuzz/corpus/$t" -type f ! -name .gitkeep | wc -l) inputs kept ($(du -sh "tests/fuzz/corpus/$t" | cut -f1))"
done
