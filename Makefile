# The user's entry points. Each target installs missing Debian packages first (idempotent),
# configures and builds with CMake, then does its job.
#   make render   -> out/default.png: VCT diffuse GI on the default scene, out/default_ao.png:
#                    its VCT ambient occlusion, out/default.json: timings and the pass plan
#   make render METHOD=gtao -> the same scene with GTAO (screen-space AO) instead
#   make test     -> the whole test suite through ctest (CPU, GPU on llvmpipe, CLI)
#   make asan     -> the suite again under AddressSanitizer + UndefinedBehaviorSanitizer
BUILD ?= build
ASAN_BUILD ?= build-asan
JOBS ?= $(shell nproc)
CMAKE_FLAGS ?= -DCMAKE_BUILD_TYPE=Release

.PHONY: deps build render test asan bench scenes results convergence convergence-gi pareto clean

deps:
	@bash scripts/install-deps.sh

METHOD ?= vct
RENDER = ./$(BUILD)/vct render scenes/default.gltf --size 512 --radius 0.5 --exposure -1

# The stamp is written only after a configure succeeded: a failed one (a missing package)
# leaves CMakeCache.txt behind, which must not pass for a finished configure.
$(BUILD)/.configured: | deps
	cmake -S . -B $(BUILD) $(CMAKE_FLAGS)
	@touch $@

build: deps $(BUILD)/.configured
	cmake --build $(BUILD) -j $(JOBS)

render: build
	@mkdir -p out
ifeq ($(METHOD),vct)
	$(RENDER) --gi vct --ao vct --voxel-res 64 -o out/default.png --stats out/default.json
	$(RENDER) --ao vct --voxel-res 64 --aov ao -o out/default_ao.png
	@echo "wrote out/default.png (VCT GI), out/default_ao.png (VCT AO); timings and pass plan in out/default.json"
else
	$(RENDER) --ao $(METHOD) -o out/default.png --stats out/default.json
	$(RENDER) --ao $(METHOD) --aov ao -o out/default_ao.png
	@echo "wrote out/default.png and out/default_ao.png ($(METHOD)); timings and pass plan in out/default.json"
endif

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

# Regenerates docs/pareto.txt: error against frame_ms and time_ms of VCT's variants, the
# reference at 1..128 spp and the denoised ray tracers (about 12 minutes on 2 cores).
pareto: build
	./$(BUILD)/bench_pareto --passes | tee docs/pareto.txt

# Regenerates docs/results.md and docs/results/*.svg from sweeps/study.json.
results: build
	python3 scripts/make_results.py --vct ./$(BUILD)/vct

# Regenerates the convergence tables of docs/convergence.md (both backends, 32^3..256^3; the
# default march, the lanes on a cubic grid, and those lanes over optical-depth levels; the total
# error of the schedule that refines the cones with the voxels; on the sparse backend, 32 cones
# in lanes and the schedule to 512^3, trilinear and with vct.sharpen=4; 6 and 32 cones in lanes
# and the schedule sharpened, parallel and aimed (vct.aim); 6 cones in lanes at the level bias,
# with the lanes' own region reach, on one alignment and pooled over five, and the schedule
# with them at 6 / 16 / 32 cones, on one alignment and pooled, with the caps below the plane
# counted open and mirrored; AO, then
# GI on the emitting families) and the Cornell box's per-surface GI table.
# The lanes' march of the later tables: 6 cones in auto lanes of base 16 on a cube, sharpened,
# aimed, texels of a quarter footprint, the lanes' reach; the resolutions and alignments pooled.
CONV_RES := 32,64,128,256
LANES16_BIAS2 := --param vct.lanes=0 --param vct.lanes-base=16 --param vct.grid=cube --param vct.sharpen=4 \
	--param vct.aim=1 --param vct.fit-reach=lanes --param vct.level-bias=-2
GRID_SHIFTS := --grid-shifts -0.5,-0.25,0,0.25,0.5

convergence: build
	./$(BUILD)/bench_convergence --res 32,64,128,256 --backend gl --markdown docs/convergence_gl.md
	./$(BUILD)/bench_convergence --res 32,64,128,256 --backend vdb --markdown docs/convergence_vdb.md
	./$(BUILD)/bench_convergence --res 32,64,128,256 --backend gl --param vct.lanes=0 --param vct.grid=cube \
		--markdown docs/convergence_gl_lanes.md
	./$(BUILD)/bench_convergence --res 32,64,128,256 --backend vdb --param vct.lanes=0 --param vct.grid=cube \
		--markdown docs/convergence_vdb_lanes.md
	./$(BUILD)/bench_convergence --res 32,64,128,256 --backend gl --param vct.lanes=0 --param vct.grid=cube \
		--param vct.opacity=depth --markdown docs/convergence_gl_lanes_depth.md
	./$(BUILD)/bench_convergence --res 32,64,128,256 --backend gl --param vct.aniso=0 --markdown docs/convergence_gl_iso.md
	./$(BUILD)/bench_convergence --res 32,64,128,256 --backend vdb --param vct.aniso=0 --markdown docs/convergence_vdb_iso.md
	./$(BUILD)/bench_convergence --schedule 64:6,128:16,256:64:64 --backend gl --param vct.grid=cube --cases ' off' \
		--markdown docs/convergence_schedule_gl.md
	./$(BUILD)/bench_convergence --schedule 64:6,128:16,256:64:64 --backend vdb --param vct.grid=cube --cases ' off' \
		--markdown docs/convergence_schedule_vdb.md
	./$(BUILD)/bench_convergence --res 128,256,512 --backend vdb --param vct.cones=32 --param vct.lanes=31 \
		--param vct.grid=cube --markdown docs/convergence_vdb_lanes32.md
	./$(BUILD)/bench_convergence --res 128,256,512 --backend vdb --param vct.cones=32 --param vct.lanes=31 \
		--param vct.grid=cube --param vct.sharpen=4 --markdown docs/convergence_vdb_lanes32_sharpen.md
	./$(BUILD)/bench_convergence --schedule 64:6,128:16,256:64:64,512:64:64 --backend vdb --param vct.grid=cube \
		--cases ' off' --markdown docs/convergence_schedule_vdb_512.md
	./$(BUILD)/bench_convergence --schedule 64:6,128:16,256:64:64,512:64:64 --backend vdb --param vct.grid=cube \
		--param vct.sharpen=4 --cases ' off' --markdown docs/convergence_schedule_vdb_512_sharpen.md
	./$(BUILD)/bench_convergence --res 32,64,128,256 --backend vdb --param vct.lanes=0 --param vct.grid=cube \
		--param vct.sharpen=4 --markdown docs/convergence_vdb_lanes_sharpen.md
	./$(BUILD)/bench_convergence --res 32,64,128,256 --backend vdb --param vct.lanes=0 --param vct.grid=cube \
		--param vct.sharpen=4 --param vct.aim=1 --markdown docs/convergence_vdb_lanes_sharpen_aim.md
	./$(BUILD)/bench_convergence --res 32,64,128,256 --backend vdb --param vct.lanes=0 --param vct.lanes-base=16 \
		--param vct.grid=cube --param vct.sharpen=4 --param vct.aim=1 --markdown docs/convergence_vdb_lanes16_sharpen_aim.md
	./$(BUILD)/bench_convergence --res 32,64,128,256 --backend vdb --param vct.lanes=0 --param vct.lanes-base=16 \
		--param vct.grid=cube --param vct.sharpen=4 --param vct.aim=1 --param vct.end-taper=1 \
		--markdown docs/convergence_vdb_lanes16_sharpen_aim_taper.md
	./$(BUILD)/bench_convergence --res 32,64,128,256 --backend vdb --param vct.lanes=0 --param vct.lanes-base=16 \
		--param vct.grid=cube --param vct.sharpen=4 --param vct.aim=1 --param vct.level-bias=-1 \
		--markdown docs/convergence_vdb_lanes16_sharpen_aim_bias.md
	./$(BUILD)/bench_convergence --res 32,64,128,256 --backend vdb --param vct.lanes=0 --param vct.lanes-base=16 \
		--param vct.grid=cube --param vct.sharpen=4 --param vct.aim=1 --param vct.level-bias=-1 \
		--param vct.fit-reach=lanes --markdown docs/convergence_vdb_lanes16_sharpen_aim_bias_reach.md
	./$(BUILD)/bench_convergence --res 32,64,128,256 --backend vdb --param vct.lanes=0 --param vct.lanes-base=16 \
		--param vct.grid=cube --param vct.sharpen=4 --param vct.aim=1 --param vct.level-bias=-1 \
		--param vct.fit-reach=lanes --cases ' off' --grid-shifts -0.5,-0.25,0,0.25,0.5 \
		--markdown docs/convergence_vdb_lanes16_sharpen_aim_bias_reach_shifts.md
	./$(BUILD)/bench_convergence --res 32,64,128,256 --backend vdb --param vct.lanes=0 --param vct.lanes-base=16 \
		--param vct.grid=cube --param vct.sharpen=4 --param vct.aim=1 --param vct.level-bias=-1 \
		--param vct.fit-reach=lanes --param vct.voxel.edges=coverage --cases ' off' \
		--markdown docs/convergence_vdb_lanes16_sharpen_aim_bias_reach_coverage.md
	./$(BUILD)/bench_convergence --res 32,64,128,256 --backend vdb --param vct.lanes=0 --param vct.lanes-base=16 \
		--param vct.grid=cube --param vct.sharpen=4 --param vct.aim=1 --param vct.level-bias=-1 \
		--param vct.fit-reach=lanes --param vct.voxel.edges=coverage --cases ' off' --grid-shifts -0.5,-0.25,0,0.25,0.5 \
		--markdown docs/convergence_vdb_lanes16_sharpen_aim_bias_reach_coverage_shifts.md
	./$(BUILD)/bench_convergence --res 32,64,128,256 --backend vdb --param vct.lanes=0 --param vct.lanes-base=16 \
		--param vct.grid=cube --param vct.sharpen=4 --param vct.aim=1 --param vct.level-bias=-2 \
		--param vct.fit-reach=lanes --cases ' off' --grid-shifts -0.5,-0.25,0,0.25,0.5 \
		--markdown docs/convergence_vdb_lanes16_sharpen_aim_bias2_reach_shifts.md
	./$(BUILD)/bench_convergence --res 32,64,128,256 --backend vdb --param vct.lanes=0 --param vct.lanes-base=16 \
		--param vct.grid=cube --param vct.sharpen=4 --param vct.aim=1 --param vct.fit-reach=lanes \
		--param vct.level-bias=-2 --param vct.voxel.edges=coverage --cases ' off' --grid-shifts -0.5,-0.25,0,0.25,0.5 \
		--markdown docs/convergence_vdb_lanes16_sharpen_aim_bias2_reach_coverage_shifts.md
	./$(BUILD)/bench_convergence --schedule 64:6,128:16,256:32 --backend vdb --param vct.lanes=0 --param vct.lanes-base=16 \
		--param vct.grid=cube --param vct.sharpen=4 --param vct.aim=1 --param vct.level-bias=-2 --param vct.fit-reach=lanes \
		--cases ' off' --markdown docs/convergence_schedule_vdb_lanes16_sharpen_aim_bias2_reach.md
	./$(BUILD)/bench_convergence --schedule 64:6,128:16,256:32 --backend vdb --param vct.lanes=0 --param vct.lanes-base=16 \
		--param vct.grid=cube --param vct.sharpen=4 --param vct.aim=1 --param vct.fit-reach=lanes --param vct.level-bias=-2 \
		--cases ' off' --grid-shifts -0.5,-0.25,0,0.25,0.5 \
		--markdown docs/convergence_schedule_vdb_lanes16_sharpen_aim_bias2_reach_shifts.md
	./$(BUILD)/bench_convergence --schedule 64:6,128:16,256:32 --backend vdb --param vct.lanes=0 --param vct.lanes-base=16 \
		--param vct.grid=cube --param vct.sharpen=4 --param vct.aim=1 --param vct.level-bias=-2 --param vct.fit-reach=lanes \
		--param vct.below-plane=mirror --cases ' off' \
		--markdown docs/convergence_schedule_vdb_lanes16_sharpen_aim_bias2_reach_mirror.md
	./$(BUILD)/bench_convergence --schedule 64:6,128:16,256:32 --backend vdb --param vct.lanes=0 --param vct.lanes-base=16 \
		--param vct.grid=cube --param vct.sharpen=4 --param vct.aim=1 --param vct.level-bias=-2 --param vct.fit-reach=lanes \
		--param vct.below-plane=mirror --cases ' off' --grid-shifts -0.5,-0.25,0,0.25,0.5 \
		--markdown docs/convergence_schedule_vdb_lanes16_sharpen_aim_bias2_reach_mirror_shifts.md
	./$(BUILD)/bench_convergence --schedule 64:6,128:16,256:32 --backend vdb --param vct.lanes=0 --param vct.lanes-base=16 \
		--param vct.grid=cube --param vct.sharpen=4 --param vct.aim=1 --param vct.fit-reach=lanes --param vct.level-bias=-2 \
		--param vct.below-plane=mirror --param vct.voxel.edges=coverage --cases ' off' \
		--markdown docs/convergence_schedule_vdb_lanes16_sharpen_aim_bias2_reach_mirror_coverage.md
	./$(BUILD)/bench_convergence --schedule 64:6,128:16,256:32 --backend vdb --param vct.lanes=0 --param vct.lanes-base=16 \
		--param vct.grid=cube --param vct.sharpen=4 --param vct.aim=1 --param vct.fit-reach=lanes --param vct.level-bias=-2 \
		--param vct.below-plane=mirror --param vct.voxel.edges=coverage --cases ' off' --grid-shifts -0.5,-0.25,0,0.25,0.5 \
		--markdown docs/convergence_schedule_vdb_lanes16_sharpen_aim_bias2_reach_mirror_coverage_shifts.md
	./$(BUILD)/bench_convergence --res $(CONV_RES) --backend vdb $(LANES16_BIAS2) --param vct.voxel.edges=coverage \
		--cases ' off' --markdown docs/convergence_vdb_lanes16_sharpen_aim_bias2_reach_coverage.md
	./$(BUILD)/bench_convergence --res $(CONV_RES) --backend vdb $(LANES16_BIAS2) --param vct.voxel.edges=sheet \
		--cases ' off' --markdown docs/convergence_vdb_lanes16_sharpen_aim_bias2_reach_sheet.md
	./$(BUILD)/bench_convergence --res $(CONV_RES) --backend gl $(LANES16_BIAS2) --param vct.voxel.edges=sheet \
		--cases ' off' --markdown docs/convergence_gl_lanes16_sharpen_aim_bias2_reach_sheet.md
	./$(BUILD)/bench_convergence --res $(CONV_RES) --backend vdb $(LANES16_BIAS2) --param vct.voxel.edges=sheet \
		--cases ' off' $(GRID_SHIFTS) --markdown docs/convergence_vdb_lanes16_sharpen_aim_bias2_reach_sheet_shifts.md
	./$(BUILD)/bench_convergence --schedule 64:6,128:16,256:32 --backend vdb $(LANES16_BIAS2) \
		--param vct.below-plane=mirror --param vct.voxel.edges=sheet --cases ' off' $(GRID_SHIFTS) \
		--markdown docs/convergence_schedule_vdb_lanes16_sharpen_aim_bias2_reach_mirror_sheet_shifts.md
	./$(BUILD)/bench_convergence --res 128,256,512 --backend vdb --param vct.cones=32 --param vct.lanes=31 \
		--param vct.grid=cube --param vct.sharpen=4 --param vct.aim=1 --markdown docs/convergence_vdb_lanes32_sharpen_aim.md
	./$(BUILD)/bench_convergence --schedule 64:6,128:16,256:64:64,512:64:64 --backend vdb --param vct.grid=cube \
		--param vct.sharpen=4 --param vct.aim=1 --cases ' off' --markdown docs/convergence_schedule_vdb_512_sharpen_aim.md
	$(MAKE) convergence-gi

convergence-gi: build
	./$(BUILD)/bench_convergence --gi --res 32,64,128,256 --backend gl --markdown docs/convergence_gi_gl.md
	./$(BUILD)/bench_convergence --gi --res 32,64,128,256 --backend vdb --markdown docs/convergence_gi_vdb.md
	./$(BUILD)/bench_convergence --gi --res 32,64,128,256 --backend gl --param vct.opacity=depth \
		--markdown docs/convergence_gi_gl_depth.md
	./$(BUILD)/bench_convergence --gi --res 32,64,128,256 --backend gl --param vct.lanes=0 --param vct.grid=cube \
		--markdown docs/convergence_gi_gl_lanes.md
	./$(BUILD)/bench_convergence --gi --res 32,64,128,256 --backend gl --param vct.lanes=0 --param vct.grid=cube \
		--param vct.opacity=depth --markdown docs/convergence_gi_gl_lanes_depth.md
	./$(BUILD)/bench_convergence --gi --res 32,64,128,256 --backend gl --param vct.aniso=0 \
		--markdown docs/convergence_gi_gl_iso.md
	# The lanes' march with the trilinear base and over sheets (32^3 and 64^3: a 128^3 case
	# takes 5-10 minutes on 2 cores).
	./$(BUILD)/bench_convergence --gi --res 32,64 --backend vdb $(LANES16_BIAS2) --param vct.voxel.edges=coverage \
		--markdown docs/convergence_gi_vdb_lanes16_sharpen_aim_bias2_coverage.md
	./$(BUILD)/bench_convergence --gi --res 32,64 --backend vdb $(LANES16_BIAS2) --param vct.voxel.edges=sheet \
		--markdown docs/convergence_gi_vdb_lanes16_sharpen_aim_bias2_sheet.md
	./$(BUILD)/bench_cornell_gi --res 32,64,128,256 --cone-model > docs/cornell_gi.txt.tmp
	./$(BUILD)/bench_cornell_gi --res 32,64,128,256 --cone-model --param vct.opacity=depth >> docs/cornell_gi.txt.tmp
	mv docs/cornell_gi.txt.tmp docs/cornell_gi.txt

clean:
	rm -rf $(BUILD) $(ASAN_BUILD) out
