# Sourced by scripts/fuzz.sh and scripts/fuzz-keep.sh (from the repository's root): the sanitizer
# build's fuzz folders, the sanitizers' settings, the targets, and each target's seeds — the same
# as tests/fuzz/CMakeLists.txt gives CTest's runs.
build=build-sanitize
fuzz=$build/fuzz
export ASAN_OPTIONS=halt_on_error=1:detect_leaks=1
export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
export LSAN_OPTIONS=suppressions=$PWD/tests/lsan.supp:print_suppressions=0
fuzz_targets=(fuzz_algorithm_input fuzz_lesson fuzz_checkpoint fuzz_timeline fuzz_scene fuzz_obj fuzz_study)

# The seed folder of target $1: written by fuzz_seeds from the registry, or the project's files.
fuzz_seeds_of() {
  case $1 in
    fuzz_lesson) echo lessons ;;
    fuzz_scene) echo tests/golden/ray-tracer ;;
    fuzz_obj) echo tests/data ;;
    *) echo "$fuzz/seeds/$1" ;;
  esac
}
