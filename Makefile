# Wraps CMake. Each target installs the Debian packages it needs first
# (scripts/setup-deps.sh TIER: nothing when they are there) and builds only
# what it runs: `make demo` the ten tools, `make test` the tools and tests.
include Makefile.inc
MAKEFLAGS += --no-print-directory

.PHONY: all deps test-deps bench-deps deb-deps configure tools build demo test test-fast \
        test-sanitize test-slow deb bench fuzz man format install clean

all: build

deps:
	@$(TIME) bash $(SETUP) build

test-deps:
	@$(TIME) bash $(SETUP) test

bench-deps:
	@$(TIME) bash $(SETUP) bench

deb-deps:
	@$(TIME) bash $(SETUP) deb

# The first configure leaves the tests out (they need the test tier);
# `make build` and `make test` turn them on.
$(BUILD_DIR)/CMakeCache.txt:
	$(TIME) $(CMAKE) -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=$(BUILD_TYPE) -DCMAKE_INSTALL_PREFIX=$(PREFIX) \
	  -DTOOLKIT_TESTS=OFF $(CMAKE_FLAGS)

# The ten tools and their gzipped man pages, nothing else.
tools: deps $(BUILD_DIR)/CMakeCache.txt
	$(TIME) $(CMAKE) --build $(BUILD_DIR) -j $(JOBS) --target toolkit_tools

demo: tools
	PATH="$(CURDIR)/$(BUILD_DIR):$$PATH" bash examples/demo.sh

# Everything the release tree holds: tools, unit tests, the test oracles.
build: deps test-deps $(BUILD_DIR)/CMakeCache.txt
	$(TIME) $(CMAKE) -S . -B $(BUILD_DIR) -DTOOLKIT_TESTS=ON > /dev/null
	$(TIME) $(CMAKE) --build $(BUILD_DIR) -j $(JOBS)

# Every test in the release build, then again under AddressSanitizer +
# UndefinedBehaviorSanitizer, except the *_oracle suites: they repeat the
# main suites' code paths at volume against PARI/GP and Python (minutes
# under the sanitizers), and the release pass already holds them; and the
# kill loops (*_faults, toolkit_fault_injection): they test what a killed
# process leaves on disk, timed by the clock, while the code they read back
# runs under the sanitizers in the unit tests and the main suites. The
# sanitizer pass builds only what it runs: the tools and unit_tests, the
# library at -O1 with line tables only (-g1), their wiring at -O0 under ASan
# alone (toolkit_compile_as_wiring): 246-249 s to build, against 527 s at -O2 -g.
# Tests that only add volume skip themselves there (skip_volume_when_sanitized).
# Each phase prints its time ("phase ... s") for CI's log.
test: test-fast test-sanitize

test-fast: build
	cd $(BUILD_DIR) && $(TIME) $(CTEST) --output-on-failure -j $(JOBS)

test-sanitize: deps test-deps
	$(TIME) $(CMAKE) -S . -B $(SANITIZE_DIR) -DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" \
	  -DTOOLKIT_SANITIZE=ON $(CMAKE_FLAGS) > /dev/null
	$(TIME) $(CMAKE) --build $(SANITIZE_DIR) -j $(JOBS) --target toolkit_tools unit_tests
	cd $(SANITIZE_DIR) && TOOLKIT_SANITIZED=1 ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
	  $(TIME) $(CTEST) --output-on-failure -j $(JOBS) -E '$(SANITIZE_EXCLUDE)'

# Slow tests outside the default suite: the seed's record primes (minutes).
test-slow: build
	TOOLKIT_BIN="$(CURDIR)/$(BUILD_DIR)" bats --jobs $(JOBS) test/slow

# build/toolkit_<version>_<arch>.deb from the release tools (see
# cmake/ToolkitPackage.cmake), then lintian on it.
deb: deb-deps tools
	cd $(BUILD_DIR) && $(CPACK) -G DEB
	lintian --info $(BUILD_DIR)/toolkit_*.deb

bench: bench-deps
	$(CMAKE) -S . -B $(BUILD_DIR) -DTOOLKIT_BENCH=ON
	$(CMAKE) --build $(BUILD_DIR) -j $(JOBS)
	PATH="$(CURDIR)/$(BUILD_DIR):$$PATH" BUILD_DIR="$(CURDIR)/$(BUILD_DIR)" bash bench/run.sh

fuzz:
	CXX=clang++ $(CMAKE) -S . -B build-fuzz -DTOOLKIT_FUZZ=ON -DTOOLKIT_TESTS=OFF -DCMAKE_BUILD_TYPE=RelWithDebInfo
	$(CMAKE) --build build-fuzz -j $(JOBS)

# Regenerates man/*.1 from the scdoc sources (the .1 files are committed).
man: deps
	for src in man/*.scd; do bash scripts/man-page.sh $$src $${src%.scd}; done

# Lays the C++ sources out as .clang-format says (the source_format test checks it).
format: test-deps
	bash scripts/format.sh

install: tools
	$(CMAKE) --install $(BUILD_DIR) --prefix $(PREFIX)

clean:
	rm -rf $(BUILD_DIR) $(SANITIZE_DIR) build-fuzz
