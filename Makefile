# softglass — the two entry points of a fresh machine, plus a few conveniences.
#   make demo   install what is missing, build (Release), run the main job
#   make test   install what is missing, build (Release), run the test suite
BUILD    ?= build
JOBS     ?= $(shell nproc)
CMAKE_FLAGS ?=

.PHONY: all deps build quiet-build test demo sanitize bench format clean

all: build

deps:
	@bash scripts/install-deps.sh

build: deps
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release $(CMAKE_FLAGS) >/dev/null
	@cmake --build $(BUILD) -j $(JOBS)

# The same build for `make demo`, its output in $(BUILD)/build.log (and the
# dependency install's in $(BUILD)/deps.log), shown only when it fails.
quiet-build:
	@bash scripts/quietly.sh $(BUILD)/deps.log "installing dependencies" bash scripts/install-deps.sh
	@bash scripts/quietly.sh $(BUILD)/build.log "build" \
	  bash -c 'cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release $(CMAKE_FLAGS) && cmake --build $(BUILD) -j $(JOBS)'

# The CI suite: everything but the long validation runs and the campaigns of
# open defects (tests/CMakeLists.txt).
test: build
	@cd $(BUILD) && ctest --output-on-failure -j $(JOBS) -LE 'validation|open-defect'

# The whole workflow: micro sweep -> bridge fit, material -> macro cone-plate
# -> macro compare with the castor-oil measurement (scripts/demo.sh).
demo: quiet-build
	@bash scripts/demo.sh $(BUILD) out/demo

# The same suite under AddressSanitizer and UndefinedBehaviorSanitizer.
sanitize: deps
	@cmake -S . -B $(BUILD)-sanitize -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSOFTGLASS_SANITIZE=ON >/dev/null
	@cmake --build $(BUILD)-sanitize -j $(JOBS)
	@cd $(BUILD)-sanitize && ctest --output-on-failure -j $(JOBS) -L sanitize

bench: build
	@bash scripts/install-deps.sh bench
	@bash bench/run_all.sh $(BUILD)

format:
	@git ls-files '*.h' '*.cpp' | xargs clang-format -i

clean:
	@rm -rf $(BUILD) $(BUILD)-sanitize
