#!/usr/bin/env bash
# Renders a fixed set of images that covers every method, both voxel backends, dense grids
# and clipmaps, AO and GI, and the voxel views, into OUTDIR (EXR, every AOV the render
# produces). Made before and after a restructuring, two sets are compared with
# `scripts/render_set.sh --compare DIR_A DIR_B`: the dense GPU path must be bit-identical.
#
#   scripts/render_set.sh build/vct out/set-before
#   scripts/render_set.sh build/vct out/set-after
#   scripts/render_set.sh --compare out/set-before out/set-after
set -euo pipefail
cd "$(dirname "$0")/.."

if [ "${1:-}" = "--compare" ]; then
  a=$2 b=$3 status=0
  for f in "$a"/*.exr; do
    name=$(basename "$f")
    if [ ! -f "$b/$name" ]; then echo "missing  $name"; status=1; continue; fi
    # idiff -a: every channel of every subimage; -fail 0 -warn 0: any difference is reported.
    if out=$(idiff -a -fail 0 -warn 0 "$f" "$b/$name" 2>&1); then
      echo "same     $name"
    else
      echo "DIFFERS  $name: $(echo "$out" | grep -E 'Mean error|RMS error|Max error' | tr -s ' ' | paste -sd ';')"
      status=1
    fi
  done
  exit $status
fi

vct=${1:?usage: render_set.sh VCT_BINARY OUTDIR | --compare DIR_A DIR_B}
out=${2:?usage: render_set.sh VCT_BINARY OUTDIR}
mkdir -p "$out"
size=64
cornell=scenes/cornell_box.gltf
overhang=scenes/offscreen_overhang.gltf
r() {  # name, then render arguments
  local name=$1; shift
  local log
  if ! log=$("$vct" render "$@" --size $size -o "$out/$name.exr" 2>&1); then echo "$log"; exit 1; fi
  echo "rendered $name"
}
for ao in ssao-crytek ssao-hemisphere ssao-horizon alchemy hbao gtao; do
  r "ao_$ao" $overhang --ao $ao --radius 1 --aov beauty,ao
done
r ao_gtao_halfres $overhang --ao gtao --radius 1 --aov ao --param ao.half-res=1
r ao_gtao_noblur $overhang --ao gtao --radius 1 --aov ao --param blur=0
r ao_vct $overhang --ao vct --radius 1 --aov beauty,ao --voxel-res 64
r ao_vct_iso $overhang --ao vct --radius 1 --aov ao --voxel-res 64 --param vct.aniso=0
r ao_vct_16 $overhang --ao vct --radius 1 --aov ao --voxel-res 64 --param vct.cones=16
r ao_vct_clipmap $overhang --ao vct --radius 1 --aov ao --voxel-res 32 --param vct.clipmap.levels=3
r ao_vct_ts4 $overhang --ao vct --radius 1 --aov ao --voxel-res 64 --param vct.trace-scale=4
r ao_vct_clipmap_ts2 $overhang --ao vct --radius 1 --aov ao --voxel-res 32 --param vct.clipmap.levels=3 --param vct.trace-scale=2
r ao_vct_depth $overhang --ao vct --radius 1 --aov ao --voxel-res 64 --param vct.opacity=depth
r ao_vct_vdb $overhang --ao vct --radius 1 --aov ao --voxel-res 64 --backend vdb
r ao_reference $overhang --ao reference --radius 1 --aov ao,ao_stderr --spp 16
r gi_vct $cornell --gi vct --aov beauty,indirect,direct --voxel-res 32
r gi_vct_ao $cornell --gi vct --ao vct --aov beauty,ao,indirect --voxel-res 32
r gi_vct_nobounce $cornell --gi vct --aov indirect --voxel-res 32 --param vct.bounces=0
r gi_vct_ts2 $cornell --gi vct --aov beauty,indirect --voxel-res 32 --param vct.trace-scale=2
r gi_vct_depth $cornell --gi vct --aov indirect --voxel-res 32 --param vct.opacity=depth
r gi_vct_iso $cornell --gi vct --aov indirect --voxel-res 32 --param vct.aniso=0
r gi_vct_clipmap $cornell --gi vct --aov indirect --voxel-res 32 --param vct.clipmap.levels=2 --param vct.bounces=0
r gi_vct_vdb $cornell --gi vct --aov indirect --voxel-res 32 --backend vdb
r gi_vct_sky $overhang --gi vct --aov beauty,indirect --voxel-res 32 --sky 0.5
r gi_reference $cornell --gi reference --aov beauty,indirect,indirect_stderr --spp 4
r views $cornell --gi vct --aov voxel_albedo,voxel_radiance,voxel_opacity,normal,depth,albedo,position,emission --voxel-res 32
r wall_base scenes/wall_base.gltf --ao gtao --radius 0.5 --aov beauty,direct,ao
