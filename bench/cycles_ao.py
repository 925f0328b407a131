# Blender Cycles' AO pass on a glTF scene, set up as the project's reference renders it, for
# bench/reference_vs_cycles.py. Run by Blender, not by Python:
#   blender -b --factory-startup --python bench/cycles_ao.py -- SCENE SIZE SPP RADIUS OUT.exr EYE TARGET FOV
# EYE and TARGET are glTF (y-up) coordinates "x,y,z"; FOV is the vertical field of view in
# degrees. Prints "CYCLES_RENDER_SECONDS s import s" (the render call, and the glTF import).
#
# Every sample is taken (no adaptive sampling, no denoising), one-pixel box filter, every
# core (as the reference's TBB), no bounces and a black world: beside the primary ray, the
# AO pass is the only work, as in the reference's pixel-area mode.
import numpy

if not hasattr(numpy, "bool"):
    numpy.bool = bool  # Debian 12's Blender 3.4 glTF importer still uses numpy.bool, gone in numpy 1.24

import math
import sys
import time

import bpy
import mathutils

argv = sys.argv[sys.argv.index("--") + 1:]
scene_path, size, spp, radius, out = argv[0], int(argv[1]), int(argv[2]), float(argv[3]), argv[4]
eye = [float(v) for v in argv[5].split(",")]
target = [float(v) for v in argv[6].split(",")]
fov = float(argv[7])

bpy.ops.wm.read_factory_settings(use_empty=True)
t0 = time.perf_counter()
bpy.ops.import_scene.gltf(filepath=scene_path)
import_seconds = time.perf_counter() - t0

scene = bpy.context.scene


def from_gltf(p):
    # glTF is y-up, Blender z-up: the importer maps (x, y, z) to (x, -z, y).
    return mathutils.Vector((p[0], -p[2], p[1]))


camera_data = bpy.data.cameras.new("camera")
camera = bpy.data.objects.new("camera", camera_data)
scene.collection.objects.link(camera)
scene.camera = camera
camera.location = from_gltf(eye)
camera.rotation_euler = (from_gltf(target) - from_gltf(eye)).to_track_quat("-Z", "Y").to_euler()
camera_data.sensor_fit = "VERTICAL"
camera_data.angle_y = math.radians(fov)
camera_data.clip_start = 0.01

render = scene.render
render.engine = "CYCLES"
render.resolution_x = render.resolution_y = size
render.resolution_percentage = 100
render.threads_mode = "AUTO"
cycles = scene.cycles
cycles.device = "CPU"
cycles.samples = spp
cycles.use_adaptive_sampling = False
cycles.use_denoising = False
cycles.max_bounces = 0
cycles.pixel_filter_type = "BOX"
cycles.filter_width = 1.0
cycles.seed = 0

world = bpy.data.worlds.new("world")
scene.world = world
world.light_settings.distance = radius  # the AO pass's ray length
world.use_nodes = True
world.node_tree.nodes["Background"].inputs[1].default_value = 0.0
scene.view_layers[0].use_pass_ambient_occlusion = True
render.image_settings.file_format = "OPEN_EXR_MULTILAYER"
render.filepath = out
render.film_transparent = True  # the sky's alpha 0: the comparison leaves it out (Cycles gives it AO 0, the reference 1)

t0 = time.perf_counter()
bpy.ops.render.render(write_still=True)
print("CYCLES_RENDER_SECONDS %.3f import %.3f" % (time.perf_counter() - t0, import_seconds))
