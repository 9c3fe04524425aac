# Thin wrapper over CMake; see README.md.
BUILD ?= build
JOBS ?= $(shell nproc 2>/dev/null || echo 2)
CMAKE_FLAGS ?=
PREFIX ?= /usr/local
DESTDIR ?=

.PHONY: all build configure demo test test-fast bench bench-large clean check-sanitize check-debug check-tsan check-fresh fuzz install uninstall

all: build

configure:
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release $(CMAKE_FLAGS) >/dev/null

build: configure
	@cmake --build $(BUILD) -j $(JOBS)

# Only the program (the test binaries are built by `make test`), then every sample in data/ meshed
# with quality into $(BUILD)/demo/, one table row and one SVG picture per file. Configure and build
# output go to $(BUILD)/demo-build.log; only a failure shows it (its last 40 lines).
demo:
	@mkdir -p $(BUILD)
	@{ cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release $(CMAKE_FLAGS) && cmake --build $(BUILD) -j $(JOBS) --target deltri; } \
	  >$(BUILD)/demo-build.log 2>&1 || { tail -n 40 $(BUILD)/demo-build.log; echo "demo: the build failed (all of it in $(BUILD)/demo-build.log)"; exit 1; }
	@sh tests/demo.sh $(BUILD)/deltri data $(BUILD)/demo

# The test readers and solvers are installed first where possible (tests/setup/install_test_deps.sh);
# the tests that need one that is missing are reported as skipped.
test: build
	@sh tests/setup/install_test_deps.sh $(BUILD)/test-deps-missing
	@cd $(BUILD) && status=0 && ctest --output-on-failure -j $(JOBS) || status=$$?; \
	  sh "$(CURDIR)/tests/setup/install_test_deps.sh" --hint test-deps-missing; exit $$status

# The `fast` tier only (tests/CMakeLists.txt: the labels fast, slow and solvers), for every push.
test-fast: build
	@cd $(BUILD) && ctest --output-on-failure -j $(JOBS) -L fast

# BENCH_THREADS="1 2 4 8" (default "1 2") sets the thread counts of the threads table, BENCH_REPEAT the rounds.
bench: build
	@python3 tests/bench/bench.py $(BUILD) $(BENCH_FLAGS)

# The 100M+ triangle workload (unit square, about 134 million triangles, ~8 GiB of memory and
# 8 GB of disk): time and peak memory for each N of BENCH_THREADS. Not run by CI or `make test`.
bench-large: build
	@python3 tests/bench/bench.py $(BUILD) --large

check-sanitize:
	@$(MAKE) --no-print-directory test BUILD=build-sanitize CMAKE_FLAGS="-DDELTRI_SANITIZE=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo"

# The end-to-end and regression tests (the program on every sample and case, checked by
# deltri_mesh_verify) on a checked build: optimised but without NDEBUG, so every run also checks the
# mesh after each stage (api/pipeline.cpp) and the invariants of src/util/invariant.h. Only the
# program, the checker, the workload generator (e2e.writer_threads) and the rename hook preloaded
# by e2e.outputs.* are built; the unit tests
# run in `make test` and `make check-sanitize`.
check-debug:
	@cmake -S . -B build-debug -DDELTRI_CHECKED=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
	@cmake --build build-debug -j $(JOBS) --target deltri deltri_preloadable deltri_mesh_verify deltri_bench_gen deltri_rename_hook
	@cd build-debug && ctest --output-on-failure -j $(JOBS) -R '^(e2e|regression)\.'

# The library's thread test (8 threads calling the C++ API at once, tests/api/test_threads.cpp)
# and refinement in 8 parts on 2 to 8 threads (tests/refine/test_parts.cpp, the test named
# halves_give_the_same_mesh_on_one_to_eight_threads) under ThreadSanitizer, which must report
# nothing: its own build, of those tests only.
check-tsan:
	@cmake -S . -B build-tsan -DDELTRI_TSAN=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
	@cmake --build build-tsan -j $(JOBS) --target test_api_threads test_refine test_io test_quality test_delaunay test_cdt test_util
	@TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1" build-tsan/tests/test_api_threads data
	@TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1" build-tsan/tests/test_refine halves_give_the_same_mesh
	@TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1" build-tsan/tests/test_io line_ranges
	@TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1" build-tsan/tests/test_io write_lines
	@TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1" build-tsan/tests/test_quality first_pass_in_two_halves
	@TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1" build-tsan/tests/test_io node_
	@TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1" build-tsan/tests/test_delaunay two_threads_give_identical_mesh
	@TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1" build-tsan/tests/test_cdt found_edges
	@TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1" build-tsan/tests/test_util run_

# The README's two commands in a fresh clone of this checkout's HEAD, from a clean environment,
# with MAKEFLAGS unset and then set to -s (tests/setup/check_fresh.sh). Not part of `make test`.
check-fresh:
	@sh tests/setup/check_fresh.sh "$(CURDIR)"

# deltri in $(PREFIX)/bin and its man page in $(PREFIX)/share/man/man1, the libraries
# (libdeltri.so.0 and libdeltri.a) in $(PREFIX)/lib, the headers in $(PREFIX)/include/deltri, the
# CMake package, the pkg-config file and the Python module (CMake's install rules; the list is
# build/install_manifest.txt). ldconfig runs after it for /usr and /usr/local as root (install.sh).
# (An existing build is installed as configured, e.g. build-sanitize; a new one is a Release build.)
install:
	@test -f $(BUILD)/CMakeCache.txt || cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release $(CMAKE_FLAGS) >/dev/null
	@cmake --build $(BUILD) -j $(JOBS) --target deltri deltri_shared deltri_static
	@sh src/api/packaging/install.sh install $(BUILD) "$(DESTDIR)" "$(PREFIX)"

# Removes exactly what `make install` with the same PREFIX and DESTDIR put there, and the folders
# it created that are empty then (install.sh keeps their list in lib/cmake/deltri).
uninstall:
	@sh src/api/packaging/install.sh uninstall "$(DESTDIR)" "$(PREFIX)"

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
	rm -rf $(BUILD) build-sanitize build-debug build-tsan build-fuzz
