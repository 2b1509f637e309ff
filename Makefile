# softgrain: the two commands are `make reproduce-figures` and `make verify` (see README.md).
BUILD  ?= build
SCALE  ?= default
OUT    ?= figures
MPIRUN ?=
JOBS   ?= $(shell nproc 2>/dev/null || echo 2)
CMAKE_FLAGS ?= -DCMAKE_BUILD_TYPE=Release
# In CI (CI set, as CI services do) a compiler warning fails the build.
ifneq ($(CI),)
CMAKE_FLAGS += -DSOFTGRAIN_WERROR=ON
endif

.PHONY: all deps configure build verify-deps verify verify-fast verify-sanitize reproduce-figures bench clean

all: build

deps:
	@scripts/install-deps

$(BUILD)/CMakeCache.txt: | deps
	cmake -S . -B $(BUILD) $(CMAKE_FLAGS)

configure: deps $(BUILD)/CMakeCache.txt

build: configure
	cmake --build $(BUILD) -j $(JOBS)

# What the tests that check output through other programs need: ParaView and VTK (the --vtk frames and the
# ParaView scripts), Chromium and Selenium (the gallery in a browser). Without them those tests would be
# reported skipped, so make verify installs them rather than pass without them.
verify-deps:
	@scripts/install-deps --vtk --browser

# Every verification law and every reproduction at smoke scale, through ctest; ends with
# 'N passed, N skipped, N failed'.
verify: build verify-deps
	@scripts/run-verification $(BUILD) $(JOBS)

# The quick loop while developing: everything not labelled slow.
verify-fast: build verify-deps
	@scripts/run-verification $(BUILD) $(JOBS) -LE slow

# The fast suite under AddressSanitizer and UndefinedBehaviorSanitizer, in its own build directory; the first
# undefined behaviour stops the process (UBSan only reports and goes on by default), so the test fails.
verify-sanitize: deps
	cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=Debug -DSOFTGRAIN_SANITIZE=ON
	cmake --build build-sanitize -j $(JOBS)
	@UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 scripts/run-verification build-sanitize $(JOBS) -LE 'slow|reproduction'

# Every figure of every paper (SCALE=smoke|default|paper) into $(OUT), then $(OUT)/index.html. Figures run in
# parallel under make -j; a failed figure does not stop the others, and the command exits non-zero naming it.
# MPIRUN="mpirun -n 64" runs the ensemble figures' runs under that MPI launcher.
reproduce-figures: build
	@$(MAKE) --no-print-directory -f scripts/figures.mk SCALE=$(SCALE) SOFTGRAIN=$(BUILD)/softgrain OUT=$(OUT) \
	  MPIRUN='$(MPIRUN)'

bench: build
	@scripts/bench $(BUILD)/softgrain

clean:
	rm -rf $(BUILD) build-sanitize out figures
