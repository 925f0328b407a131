#!/bin/bash
# The GPU checks of docs/gpu.md on a machine that has a GPU and its EGL driver but not
# Debian's packages, from a bundle made on the build machine by scripts/portable_bundle.py
# (vct, vct_tests_gpu, vct_tests_cli, vct_tests_stability and bench_pareto, Sponza as a scene):
#
#   scripts/gpu_check.sh BUNDLE.tar.xz OUT_DIR [--pareto]
#
# Run from a checkout of the same commit. Writes OUT_DIR/gpu_check.log, the tests' logs,
# the default scene's renders and stats, and with --pareto the Pareto table.
set -u
bundle=$1 out=$2 pareto=${3:-}
mkdir -p "$out"
exec > >(tee "$out/gpu_check.log") 2>&1
t0=$(date +%s); stamp() { echo "== [$(( $(date +%s) - t0 )) s] $*"; }
here=$(mktemp -d)
tar -C "$here" -xf "$bundle" || exit 1
b=$here/bundle
# The tests run `vct` and read scenes at the paths the build baked in: point those at this
# checkout and the bundle where nothing is there.
source_dir=$(sed -n 's/^source=//p' "$b/paths") build_dir=$(sed -n 's/^build=//p' "$b/paths")
[ -e "$source_dir" ] || { mkdir -p "$(dirname "$source_dir")" && ln -s "$PWD" "$source_dir"; }
[ -e "$build_dir/vct" ] || { mkdir -p "$build_dir" && cp "$b"/bin/* "$build_dir/"; }
export LD_LIBRARY_PATH="$b/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
export VCT_SHARED_SCENES=$b/scenes VCT_GL_DEVICE=${VCT_GL_DEVICE:-device}
stamp info
"$b/bin/vct" info scenes/default.gltf --gl-device $VCT_GL_DEVICE || exit 1
stamp render
r="scenes/default.gltf --size 512 --radius 0.5 --exposure -1 --voxel-res 64 --gl-device $VCT_GL_DEVICE"
"$b/bin/vct" render $r --gi vct --ao vct -o "$out/default.png" --stats "$out/default.json"
"$b/bin/vct" render $r --ao vct --aov ao -o "$out/default_ao.png"
stamp gpu tests
"$b/bin/vct_tests_gpu" > "$out/gpu_tests.log" 2>&1; echo "vct_tests_gpu: exit $?"
grep -E "^\[  (PASSED|FAILED|SKIPPED) " "$out/gpu_tests.log"
stamp cli tests
"$b/bin/vct_tests_cli" > "$out/cli_tests.log" 2>&1; echo "vct_tests_cli: exit $?"
grep -E "^\[  (PASSED|FAILED|SKIPPED) " "$out/cli_tests.log"
stamp stability tests
"$b/bin/vct_tests_stability" > "$out/stability_tests.log" 2>&1; echo "vct_tests_stability: exit $?"
grep -E "^\[  (PASSED|FAILED|SKIPPED) " "$out/stability_tests.log"
if [ "$pareto" = --pareto ]; then
    stamp pareto
    "$b/bin/bench_pareto" --passes > "$out/pareto.txt" 2>"$out/pareto_progress.log"; echo "bench_pareto: exit $?"
fi
stamp done
