# kestrel: the two commands a new user needs are `make demo` and `make test`.
BUILD     ?= build
JOBS      ?= $(shell nproc)
DEMO_OUT  ?= out/demo
GENERATOR := $(shell command -v ninja >/dev/null 2>&1 && echo "-G Ninja")

.PHONY: all deps configure build test demo bench soak format package test-asan test-tsan clean

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

# Installs dependencies, builds, runs the default graph and writes $(DEMO_OUT)/report.{json,md}.
demo: deps
	$(MAKE) build
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

# The test suite under sanitizers, in their own build folders.
test-asan: deps
	cmake -S . -B build-asan $(GENERATOR) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DKESTREL_SANITIZE=address,undefined -DKESTREL_BUILD_BENCH=OFF
	cmake --build build-asan -j $(JOBS)
	ctest --test-dir build-asan --output-on-failure -j $(JOBS) -E out_of_tree

test-tsan: deps
	cmake -S . -B build-tsan $(GENERATOR) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DKESTREL_SANITIZE=thread -DKESTREL_BUILD_BENCH=OFF
	cmake --build build-tsan -j $(JOBS)
	ctest --test-dir build-tsan --output-on-failure -j $(JOBS) -E out_of_tree

clean:
	rm -rf $(BUILD) build-asan build-tsan out
