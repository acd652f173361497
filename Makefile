# The two commands of the README. Each does all of its set-up itself.
BUILD  ?= build
JOBS   ?= $(shell nproc)
CMAKE_FLAGS ?=

.PHONY: all deps build demo test bench package sanitize fuzz clean

all: build

deps:
	@scripts/install-deps

$(BUILD)/CMakeCache.txt: | deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release $(CMAKE_FLAGS)

build: deps $(BUILD)/CMakeCache.txt
	cmake --build $(BUILD) -j $(JOBS)

demo: build
	@scripts/demo $(BUILD)/cemv

# The suite, then how many tests waited for the published tables that cannot
# ship with the project (README, "Tests that read published data").
test: build
	@cd $(BUILD) && { ctest --output-on-failure -j $(JOBS); echo $$? > ctest.status; } 2>&1 | tee ctest.log
	@scripts/external-summary $(BUILD)/ctest.log
	@exit $$(cat $(BUILD)/ctest.status)

bench: build
	@scripts/bench $(BUILD)

# The Debian package of what `make` built (docs/ci.md, "Installing cemv"):
# $(BUILD)/cemv_VERSION_ARCH.deb, copied here, so that
# `apt-get install ./cemv_*.deb` installs it. scripts/build-package makes the
# same package from the slim build (no tests, no benchmarks), as CI does.
package: build
	rm -f $(BUILD)/cemv_*.deb ./cemv_*.deb
	cmake --build $(BUILD) --target package
	cp $(BUILD)/cemv_*.deb .

# ASan + UBSan build of everything, running the whole suite (slower).
sanitize: deps
	cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=Debug -DCEMV_SANITIZE=ON -DCEMV_BENCH=OFF
	cmake --build build-sanitize -j $(JOBS)
	cd build-sanitize && ctest --output-on-failure -j $(JOBS)

# The libFuzzer targets of the importers (docs/fuzzing.md): clang-14 with ASan
# and UBSan in their own build dir, then each target for FUZZ_SECONDS (default
# 600) over its corpus in fuzz/corpus/, new inputs in build-fuzz/scratch/,
# findings in build-fuzz/findings/. `make fuzz FUZZ_SECONDS=60` for a short run;
# FUZZ_TARGETS="csv scenario" for some of them.
FUZZ_SECONDS ?= 600
FUZZ_TARGETS ?=
fuzz:
	@scripts/install-deps fuzz
	cmake -S . -B build-fuzz -DCEMV_FUZZ=ON -DCMAKE_CXX_COMPILER=clang++-14 -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCEMV_BENCH=OFF
	cmake --build build-fuzz -j $(JOBS) --target fuzz_targets
	FUZZ_BUILD=build-fuzz FUZZ_SECONDS=$(FUZZ_SECONDS) fuzz/run.sh $(FUZZ_TARGETS)

clean:
	rm -rf $(BUILD) build-sanitize build-fuzz
