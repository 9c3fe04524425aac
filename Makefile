# Thin wrapper over CMake; see README.md.
BUILD ?= build
JOBS ?= $(shell nproc 2>/dev/null || echo 2)
CMAKE_FLAGS ?=

.PHONY: all build demo test bench clean check-sanitize fuzz

all: build

build:
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release $(CMAKE_FLAGS) >/dev/null
	@cmake --build $(BUILD) -j $(JOBS)

demo: build
	@sh tests/demo.sh $(BUILD)/deltri data

test: build
	@cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

bench: build
	@python3 tests/bench/bench.py $(BUILD) $(BENCH_FLAGS)

check-sanitize:
	@$(MAKE) --no-print-directory test BUILD=build-sanitize CMAKE_FLAGS="-DDELTRI_SANITIZE=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo"

# libFuzzer with clang, separate from the g++ build; see docs/reliability.md. Not part of CI.
FUZZ_SECONDS ?= 60
FUZZ_TARGET ?= fuzz_pipeline
# e.g. FUZZ_FLAGS="-fork=1 -ignore_crashes=1" to go on after a finding (one worker process)
FUZZ_FLAGS ?=
fuzz:
	@cmake -S . -B build-fuzz -DCMAKE_CXX_COMPILER=clang++ -DDELTRI_FUZZ=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
	@cmake --build build-fuzz -j $(JOBS) --target $(FUZZ_TARGET)
	@sh tests/fuzz/run.sh $(CURDIR)/build-fuzz $(FUZZ_TARGET) $(FUZZ_SECONDS) "$(FUZZ_FLAGS)"

clean:
	rm -rf $(BUILD) build-sanitize build-fuzz
