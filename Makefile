# CG Sandbox — the two commands:
#   make run    install what is missing, build, and open the viewer
#   make test   install what is missing, build, and run every test (GUI tests under xvfb-run)
# and a few more: make build, make bench, make clean.
.PHONY: all deps configure build run test bench clean

all: build

deps:
	@scripts/install-deps.sh

configure: deps
	@cmake --preset default >/dev/null

build: configure
	@cmake --build --preset default

run: build
	@build/bin/cgsandbox

test: build
	@ctest --preset default

bench: build
	@build/bin/cgbench

clean:
	rm -rf build
