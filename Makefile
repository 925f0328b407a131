# The user's entry points. Each target installs missing Debian packages first (idempotent),
# configures and builds with CMake, then does its job.
#   make render   -> out/default.png (the default scene, screen-space AO)
#   make test     -> the whole test suite through ctest (CPU, GPU on llvmpipe, CLI)
#   make asan     -> the suite again under AddressSanitizer + UndefinedBehaviorSanitizer
BUILD ?= build
ASAN_BUILD ?= build-asan
JOBS ?= $(shell nproc)
CMAKE_FLAGS ?= -DCMAKE_BUILD_TYPE=Release

.PHONY: deps build render test asan bench scenes results clean

deps:
	@bash scripts/install-deps.sh

$(BUILD)/CMakeCache.txt: | deps
	cmake -S . -B $(BUILD) $(CMAKE_FLAGS)

build: deps $(BUILD)/CMakeCache.txt
	cmake --build $(BUILD) -j $(JOBS)

render: build
	@mkdir -p out
	./$(BUILD)/vct render scenes/default.gltf --size 512 --ao gtao --radius 0.5 --exposure -1.5 -o out/default.png --stats out/default.json
	@echo "wrote out/default.png (timings and pass plan in out/default.json)"

test: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS) --timeout 900

asan: deps
	cmake -S . -B $(ASAN_BUILD) -DCMAKE_BUILD_TYPE=Debug -DVCT_SANITIZE=ON
	cmake --build $(ASAN_BUILD) -j $(JOBS)
	cd $(ASAN_BUILD) && ASAN_OPTIONS=detect_leaks=1 LSAN_OPTIONS=suppressions=$(CURDIR)/scripts/lsan.supp \
		ctest --output-on-failure -j $(JOBS) -L "cpu|gpu" --timeout 1800

scenes: build
	./$(BUILD)/vct-scenegen scenes

bench: build
	@for b in $(BUILD)/bench_*; do echo "== $$b"; ./$$b; done

# Regenerates docs/results.md and docs/results/*.svg from sweeps/study.json.
results: build
	python3 scripts/make_results.py --vct ./$(BUILD)/vct

clean:
	rm -rf $(BUILD) $(ASAN_BUILD) out
