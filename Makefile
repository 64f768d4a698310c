# The README's two commands on a fresh machine:
#   make verify   install what is missing, build (Release), run the verification suite
#   make test     install what is missing, build, run every test (ctest)
BUILD_DIR ?= build
JOBS      ?= $(shell nproc 2>/dev/null || echo 2)
CMAKE_FLAGS ?=

.PHONY: all setup configure build verify test bench clean

all: build

setup:
	@bash scripts/setup.sh

configure: setup
	cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=Release $(CMAKE_FLAGS)

build: configure
	cmake --build $(BUILD_DIR) -j $(JOBS)

# The suite's exit status is kept; the report is written whatever it says.
verify: build
	@status=0; \
	$(BUILD_DIR)/catena verify --scenes verification/scenes --out $(BUILD_DIR)/report || status=$$?; \
	$(BUILD_DIR)/catena report --from $(BUILD_DIR)/report/report.json --out $(BUILD_DIR)/report || status=$$?; \
	echo "report: $(BUILD_DIR)/report/report.html (and report.md)"; \
	exit $$status

test: build
	cd $(BUILD_DIR) && ctest --output-on-failure -j $(JOBS)

bench: setup
	cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=Release -DCATENA_BUILD_BENCHMARKS=ON $(CMAKE_FLAGS)
	cmake --build $(BUILD_DIR) -j $(JOBS)

clean:
	rm -rf $(BUILD_DIR)
