# Wraps CMake. `make demo` and `make test` install what is missing first.
include Makefile.inc

.PHONY: all deps test-deps bench-deps build demo test test-fast test-sanitize test-slow \
        bench fuzz man install clean

all: build

deps:
	@bash $(SETUP) build

test-deps:
	@bash $(SETUP) test

bench-deps:
	@bash $(SETUP) bench

$(BUILD_DIR)/CMakeCache.txt:
	$(CMAKE) -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=$(BUILD_TYPE) -DCMAKE_INSTALL_PREFIX=$(PREFIX) $(CMAKE_FLAGS)

build: deps test-deps $(BUILD_DIR)/CMakeCache.txt
	$(CMAKE) --build $(BUILD_DIR) -j $(JOBS)

demo: build
	PATH="$(CURDIR)/$(BUILD_DIR):$$PATH" bash examples/demo.sh

# Every test in the release build, then again under AddressSanitizer +
# UndefinedBehaviorSanitizer, except the *_oracle suites: they repeat the
# main suites' code paths at volume against PARI/GP and Python (minutes
# under the sanitizers), and the release pass already holds them; and the
# kill loops (*_faults, toolkit_fault_injection): they test what a killed
# process leaves on disk, timed by the clock, while the code they read back
# runs under the sanitizers in the unit tests and the main suites.
test: test-fast test-sanitize

test-fast: build
	cd $(BUILD_DIR) && $(CTEST) --output-on-failure -j $(JOBS)

test-sanitize: deps test-deps
	$(CMAKE) -S . -B $(SANITIZE_DIR) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTOOLKIT_SANITIZE=ON $(CMAKE_FLAGS)
	$(CMAKE) --build $(SANITIZE_DIR) -j $(JOBS)
	cd $(SANITIZE_DIR) && TOOLKIT_SANITIZED=1 ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
	  $(CTEST) --output-on-failure -j $(JOBS) -E '_oracle$$|_faults$$|fault_injection$$'

# Slow tests outside the default suite: the seed's record primes (minutes).
test-slow: build
	TOOLKIT_BIN="$(CURDIR)/$(BUILD_DIR)" bats --jobs $(JOBS) test/slow

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

install: build
	$(CMAKE) --install $(BUILD_DIR) --prefix $(PREFIX)

clean:
	rm -rf $(BUILD_DIR) $(SANITIZE_DIR) build-fuzz
