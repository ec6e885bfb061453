# kestrel: the two commands a new user needs are `make demo` and `make test`.
BUILD     ?= build
JOBS      ?= $(shell nproc)
DEMO_OUT  ?= out/demo
GENERATOR := $(shell command -v ninja >/dev/null 2>&1 && echo "-G Ninja")

.PHONY: all deps configure build product test demo bench soak format package test-asan test-tsan fuzz fuzz-smoke clean

all: build

deps:
	scripts/install-deps

# Configures once; later builds re-run CMake by themselves when needed. A folder with no build
# system (build.ninja or Makefile) never configured successfully, for instance before `make deps`:
# its cache is dropped and CMake runs afresh, perhaps with another generator now that ninja exists.
configure:
	@if [ ! -f $(BUILD)/build.ninja ] && [ ! -f $(BUILD)/Makefile ]; then \
	  rm -rf $(BUILD)/CMakeCache.txt $(BUILD)/CMakeFiles; \
	  cmake -S . -B $(BUILD) $(GENERATOR) -DCMAKE_BUILD_TYPE=Release; \
	fi

# Release build; the CLI lands at build/bin/kestrel.
build: configure
	cmake --build $(BUILD) -j $(JOBS)

# Installs dependencies, builds, runs every test.
test: deps
	$(MAKE) build
	ctest --test-dir $(BUILD) --output-on-failure -j $(JOBS)

# Only what a user runs: the CLI, the libraries and the plugins (no tests, no benchmarks).
product: configure
	cmake --build $(BUILD) -j $(JOBS) --target product

# Installs dependencies, builds the product, runs the default graph and writes
# $(DEMO_OUT)/report.{json,md}.
demo: deps
	$(MAKE) product
	scripts/demo $(DEMO_OUT)

bench: build
	scripts/bench out/bench

# Ten minutes of a realtime graph, sampling RSS (see docs/benchmarks.md).
soak: build
	scripts/soak-rss out/soak 600

# A Debian package of the Release build, $(BUILD)/kestrel_<version>-1_<arch>.deb, installing under /usr.
package: build
	cd $(BUILD) && cpack -G DEB

format:
	git ls-files '*.cpp' '*.hpp' '*.h' | xargs clang-format -i

# The sanitizer and fuzz builds, each in its own folder: -O1 with line tables builds and runs
# fast and still gives readable stacks; no benchmarks (docs/testing.md). Both are built by clang-14
# (a third faster to build than GCC, and a second compiler's warnings) and linked by its lld.
SAN_CMAKE := $(GENERATOR) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DKESTREL_BUILD_BENCH=OFF \
  -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" \
  -DCMAKE_C_COMPILER=clang-14 -DCMAKE_CXX_COMPILER=clang++-14 -DCMAKE_EXE_LINKER_FLAGS=-fuse-ld=lld \
  -DCMAKE_SHARED_LINKER_FLAGS=-fuse-ld=lld -DCMAKE_MODULE_LINKER_FLAGS=-fuse-ld=lld
SAN_DIR := $(CURDIR)/tests/sanitizers
# intercept_tls_get_addr=0: GCC 12's (and LLVM 14's) __tls_get_addr interceptor takes a malloc'd
# dynamic TLS block that happens to sit 16 bytes past a page boundary for a glibc 2.19 header and
# records a bogus range, which LeakSanitizer's tracer then reads at exit and dies on ("Tracer
# caught signal 11"). Dynamic TLS blocks are heap chunks reachable from each thread's DTV, so
# leak checking loses nothing (docs/testing.md).
ASAN_ENV := ASAN_OPTIONS=detect_leaks=1:intercept_tls_get_addr=0:check_initialization_order=1:strict_init_order=1:detect_stack_use_after_return=1 \
  LSAN_OPTIONS=suppressions=$(SAN_DIR)/lsan.supp:print_suppressions=0 \
  UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
# The tests test-asan leaves out, one exact name per line with the reason (tests/sanitizers).
ASAN_SKIP := ^($(shell grep -v -e '^\#' -e '^$$' $(SAN_DIR)/asan-skip.txt | sed 's/[.]/[.]/g' | paste -sd'|'))$$
TSAN_ENV := TSAN_OPTIONS=halt_on_error=1:second_deadlock_stack=1:suppressions=$(SAN_DIR)/tsan.supp
# The ASan test suite and the fuzz targets share one clang-14 build folder: the fuzz targets, and
# the libraries they reach, also carry coverage instrumentation (tests/fuzz/CMakeLists.txt).
ASAN_BUILD := build-asan
ASAN_CMAKE := $(SAN_CMAKE) -DKESTREL_SANITIZE=address,undefined,float-cast-overflow -DKESTREL_BUILD_FUZZ=ON
FUZZ_SECONDS ?= 10

# The whole test suite under AddressSanitizer (with LeakSanitizer) and UndefinedBehaviorSanitizer,
# but for the reruns listed in tests/sanitizers/asan-skip.txt (a program all of whose tests are
# listed is not built: kestrel_add_test ASAN_SKIPPED; check_asan_skip.py checks the list).
# out_of_tree_plugin is left out: it installs the build and compiles a separate CMake project
# (examples/hello_plugin) with its own, uninstrumented flags, so it tests packaging, not our code
# under the sanitizers; `make test` runs it.
test-asan: deps
	cmake -S . -B $(ASAN_BUILD) $(ASAN_CMAKE)
	cmake --build $(ASAN_BUILD) -j $(JOBS)
	python3 $(SAN_DIR)/check_asan_skip.py $(SAN_DIR)/asan-skip.txt $(ASAN_BUILD) $(BUILD)
	$(ASAN_ENV) ctest --test-dir $(ASAN_BUILD) --output-on-failure -j $(JOBS) -E '$(ASAN_SKIP)'

# The threaded tests (CTest label `threads`: realtime executor, its queues, signal shutdown)
# under ThreadSanitizer; only the targets they need are built.
test-tsan: deps
	cmake -S . -B build-tsan $(SAN_CMAKE) -DKESTREL_SANITIZE=thread
	cmake --build build-tsan -j $(JOBS) --target kestrel_framework_tests kestrel_cli_tests kestrel_write_queue_tests \
	  kestrel_live_server_tests kestrel_recorder_thread_tests kestrel_mavlink_tests kestrel_mavlink_source_tests
	$(TSAN_ENV) ctest --test-dir build-tsan --output-on-failure -j $(JOBS) -L threads

# libFuzzer targets (tests/fuzz), built with clang-14 under ASan and UBSan in test-asan's folder
# (after test-asan, nothing is left to configure or build: a configured folder is not configured
# again, and the build re-runs CMake itself if a CMakeLists.txt changed).
fuzz: deps
	@if ! grep -qsE '^KESTREL_BUILD_FUZZ:[A-Z]+=ON$$' $(ASAN_BUILD)/CMakeCache.txt || \
	    { [ ! -f $(ASAN_BUILD)/build.ninja ] && [ ! -f $(ASAN_BUILD)/Makefile ]; }; then \
	  cmake -S . -B $(ASAN_BUILD) $(ASAN_CMAKE); fi
	cmake --build $(ASAN_BUILD) -j $(JOBS) --target kestrel_fuzz

# Each fuzz target for FUZZ_SECONDS on a scratch copy of its committed corpus; fails on a crash.
# FUZZ_TARGETS="mot_reader ..." limits it to some targets.
fuzz-smoke: fuzz
	scripts/fuzz-smoke $(ASAN_BUILD) $(FUZZ_SECONDS)

clean:
	rm -rf $(BUILD) $(ASAN_BUILD) build-tsan out
