# CG Sandbox — the two commands:
#   make run    install what is missing, build, and open the viewer
#   make test   install what is missing, build the desktop viewer and the browser build, and run
#               every test (GUI tests under xvfb-run, the browser test in headless Chromium);
#               then build the sanitizer configuration and run the whole suite again under
#               AddressSanitizer + UBSan, with a 30-second run of each fuzz target
# and a few more: make build, make test-normal, make test-sanitize, make bench, make fuzz,
# make screenshots, make contact-sheets, make clean; and the browser build: make web,
# make serve-web, make test-web.
.PHONY: all deps configure build build-sanitize run test test-normal test-sanitize bench fuzz \
	screenshots contact-sheets clean web serve-web test-web

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

# Only what the viewer needs (the library and cgsandbox), not every test and benchmark.
run: configure
	@cmake --build --preset default --target cgsandbox
	@build/bin/cgsandbox

test: test-normal test-sanitize

# The normal suite includes the browser test (web_browser, tests/web/), so the site is built
# first; CG_WEB_REQUIRED turns its "no site, skipped" into a failure.
test-normal: build web
	@CG_WEB_REQUIRED=1 ctest --preset default

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

# The viewer in a browser (docs/web.md): WebAssembly + WebGL 2 into build-web/site/, a static
# folder for any web server; its own dependencies (emscripten, SDL2 and Dear ImGui sources,
# Chromium for the test) are installed by scripts/install-web-deps.sh, only for these targets.
WEB_PORT ?= 8080
web:
	@scripts/web-build.sh

serve-web: web
	@echo "CG Sandbox: http://127.0.0.1:$(WEB_PORT)/ (Ctrl-C stops)"
	@python3 -m http.server $(WEB_PORT) --bind 127.0.0.1 --directory build-web/site

# The browser test (tests/web/): headless Chromium on the built site.
test-web: web
	@/usr/bin/python3 tests/web/test_web.py build-web/site

# Every lesson's presets at their first, middle and last step, one sheet a lesson, for looking
# over the pictures as a student meets them: build/contact-sheets/<lesson>.png (the canvas of a
# 1280×720 window; SHEET_SIZE=1920x1080 for the other size, LESSONS="id …" for some only).
SHEET_SIZE ?= 1280x720
contact-sheets: build
	@build/bin/cgsandbox contact-sheet $(LESSONS) --size $(SHEET_SIZE) --out-dir build/contact-sheets

clean:
	rm -rf build build-sanitize build-bench build-web/cmake build-web/site
