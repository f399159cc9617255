# CG Sandbox — the two commands:
#   make run    install what is missing, build, and open the viewer
#   make test   install what is missing, build, and run every test (GUI tests under xvfb-run),
#               then build the sanitizer configuration and run the whole suite again under
#               AddressSanitizer + UBSan, with a 30-second run of each fuzz target
# and a few more: make build, make test-normal, make test-sanitize, make bench, make fuzz,
# make screenshots, make clean.
.PHONY: all deps configure build build-sanitize run test test-normal test-sanitize bench fuzz \
	screenshots clean

FUZZ_SECONDS ?= 600

all: build

deps:
	@scripts/install-deps.sh

configure: deps
	@cmake --preset default >/dev/null

build: configure
	@cmake --build --preset default

build-sanitize: deps
	@cmake --preset sanitize >/dev/null
	@cmake --build --preset sanitize

run: build
	@build/bin/cgsandbox

test: test-normal test-sanitize

test-normal: build
	@ctest --preset default

test-sanitize: build-sanitize
	@ctest --preset sanitize

# The benchmarks are built apart, with link-time optimisation (the `bench` preset, build-bench/);
# cgbench repeats each benchmark three times (medians), and the run ends with the table of every
# state machine's cost against its plain function (cgbench_ratios, ⚠ past 1.25×).
bench: deps
	@cmake --preset bench >/dev/null
	@cmake --build --preset bench
	@build-bench/bin/cgbench --benchmark_repetitions=3 --benchmark_report_aggregates_only=true \
		--benchmark_out=build-bench/cgbench.json --benchmark_out_format=json
	@build-bench/bin/cgbench_mesh
	@env -u DISPLAY build-bench/bin/cgbench_frames
	@build-bench/bin/cgbench_ratios build-bench/cgbench.json 1.25

# Each fuzz target for FUZZ_SECONDS (default 600), growing build-sanitize/fuzz/corpus/.
fuzz: build-sanitize
	@scripts/fuzz.sh $(FUZZ_SECONDS)

# The README's pictures (docs/images/*.png), drawn by the built viewer: scripts/screenshots.sh.
screenshots: build
	@scripts/screenshots.sh build/bin/cgsandbox docs/images

clean:
	rm -rf build build-sanitize build-bench
