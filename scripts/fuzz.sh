#!/usr/bin/env bash
# Runs each fuzz target of the sanitizer build for SECONDS (default 600), from the seeds and
# the corpus grown so far (build-sanitize/fuzz/corpus/<target>, kept between runs), and prints
# per target: seconds, executions, corpus size, and whether it found anything. A crash leaves
# its input in build-sanitize/fuzz/artifacts/; fix it and copy the input into
# tests/fuzz/regressions/<target>/.
set -uo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-600}
source scripts/fuzz-common.sh
"$build/bin/fuzz_seeds" "$fuzz/seeds" lessons || exit 1
mkdir -p "$fuzz/artifacts" "$fuzz/logs"
# The targets run FUZZ_JOBS at a time (default: one per core), each for its full SECONDS of wall
# time; their summaries print in the fixed order below once all have finished.
jobs=${FUZZ_JOBS:-$(nproc)}
targets=("${fuzz_targets[@]}")
run_target() {
  local t=$1 seeds
  seeds=$(fuzz_seeds_of "$t")
  mkdir -p "$fuzz/corpus/$t"
  local log=$fuzz/logs/$t.log
  "$build/bin/$t" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=8192 \
    -print_final_stats=1 -artifact_prefix="$fuzz/artifacts/$t-" \
    "$fuzz/corpus/$t" "tests/fuzz/corpus/$t" "$seeds" "tests/fuzz/regressions/$t" >"$log" 2>&1
  echo $? >"$fuzz/logs/$t.rc"
}
for t in "${targets[@]}"; do
  while (( $(jobs -rp | wc -l) >= jobs )); do wait -n; done
  run_target "$t" &
done
wait
status=0
for t in "${targets[@]}"; do
  log=$fuzz/logs/$t.log
  rc=$(cat "$fuzz/logs/$t.rc")
  execs=$(grep -o 'stat::number_of_executed_units: [0-9]*' "$log" | grep -o '[0-9]*$')
  found=$([[ $rc == 0 ]] && echo "nothing" || echo "FAILED (exit $rc, see $log)")
  echo "$t: ${seconds} s, ${execs:-?} executions, corpus $(ls "$fuzz/corpus/$t" | wc -l) files, found: $found"
  grep '^algorithm' "$log" | sed 's/^/    /'
  [[ $rc == 0 ]] || status=1
done
exit $status
