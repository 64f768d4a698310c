# SPDX-License-Identifier: MIT
# The README's two commands on a fresh machine:
#   make verify   install what is missing, build (Release), run the verification suite
#   make test     install what is missing, build, run every test (ctest)
#   make test-sanitize   the same tests and part of the suite under ASan + UBSan (docs/contributing/testing.md)
#   make fuzz-campaign   5000 mutants each of scenes, MoorDyn decks, check results and report --from
#                        files through the CLI, fixed seed (docs/contributing/testing.md)
BUILD_DIR ?= build
JOBS      ?= $(shell nproc 2>/dev/null || echo 2)
CMAKE_FLAGS ?=

.PHONY: all setup configure build verify test test-sanitize fuzz-campaign bench clean

all: build

setup:
	@bash scripts/setup.sh

configure: setup
	cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=Release $(CMAKE_FLAGS)

build: configure
	cmake --build $(BUILD_DIR) -j $(JOBS)

# The suite's exit status is kept; the report is written whatever it says. Before the report, the
# validity maps' sweeps (verification/sweeps/<map>-coarse.toml, VALIDITY=full: <map>.toml, 1e4
# points each) write $(BUILD_DIR)/report/validity/<map>/points.csv, which `catena report` draws
# (docs/explanation/validity-maps.md). A sweep resumes what its directory holds; one refused (its
# directory holds another spec's points) starts again in an emptied directory.
VALIDITY ?= coarse
VALIDITY_MAPS ?= level inclined
verify: build
	@status=0; \
	$(BUILD_DIR)/catena verify --scenes verification/scenes --out $(BUILD_DIR)/report || status=$$?; \
	for map in $(VALIDITY_MAPS); do \
	  spec=verification/sweeps/$$map$(if $(filter full,$(VALIDITY)),,-$(VALIDITY)).toml; \
	  dir=$(BUILD_DIR)/report/validity/$$map; \
	  $(BUILD_DIR)/catena sweep $$spec --out $$dir --quiet || \
	    { rm -rf $$dir; $(BUILD_DIR)/catena sweep $$spec --out $$dir --quiet; } || status=$$?; \
	done; \
	$(BUILD_DIR)/catena report --from $(BUILD_DIR)/report/report.json --out $(BUILD_DIR)/report || status=$$?; \
	echo "report: $(BUILD_DIR)/report/report.html (and report.md)"; \
	exit $$status

test: build
	cd $(BUILD_DIR) && ctest --output-on-failure -j $(JOBS)

# AddressSanitizer + UndefinedBehaviorSanitizer (with float-cast-overflow) in its own build
# directory, -O1 with assert()s on: the unit tests, a shorter fuzz run, and the scene families in
# SANITIZE_FILTERS through `catena verify` (one --filter each; SANITIZE_FILTERS=all runs the
# whole suite). Any sanitizer report aborts the process, so the target fails.
SANITIZE_DIR     ?= build-sanitize
SANITIZE_FILTERS ?= analytic physical grinfogel stress-deep-sag curves gale-b-3-hb0.50
test-sanitize: setup
	cmake -S . -B $(SANITIZE_DIR) -DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g" \
	      -DCATENA_SANITIZE=ON -DCATENA_FUZZ_ITERATIONS=500 $(CMAKE_FLAGS)
	cmake --build $(SANITIZE_DIR) -j $(JOBS)
	cd $(SANITIZE_DIR) && ctest --output-on-failure -j $(JOBS) -E '^(verification_suite|report_in_browser)$$'
	@if [ "$(SANITIZE_FILTERS)" = all ]; then \
	  $(SANITIZE_DIR)/catena verify --scenes verification/scenes --quiet --out $(SANITIZE_DIR)/report; \
	else for family in $(SANITIZE_FILTERS); do \
	  echo "sanitized suite: scenes matching '$$family'"; \
	  $(SANITIZE_DIR)/catena verify --scenes verification/scenes --filter $$family --quiet \
	      --out $(SANITIZE_DIR)/report-$$family || exit 1; \
	done; fi

# The mutant campaign (scripts/fuzz_campaign.py) on the Release build: 5000 mutants of each
# target, seed 18; every target runs, and the target fails if any of them found a failure.
FUZZ_TARGETS ?= scene moordyn check report
fuzz-campaign: build
	@status=0; for target in $(FUZZ_TARGETS); do \
	  python3 scripts/fuzz_campaign.py --build $(BUILD_DIR) --no-build --target $$target || status=1; \
	done; exit $$status

bench: setup
	cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=Release -DCATENA_BUILD_BENCHMARKS=ON $(CMAKE_FLAGS)
	cmake --build $(BUILD_DIR) -j $(JOBS)

clean:
	rm -rf $(BUILD_DIR)
