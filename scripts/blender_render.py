# Renders one frame of a `simhuman export --gltf` scene with Blender (Cycles on the CPU, no GPU
# or display needed):
#   blender -b --python scripts/blender_render.py -- scene.glb out.png [--time 2.5]
#       [--size 640x360] [--samples 16]
# The camera looks at the first human's pelvis from its front-left, 3.5 m away; a sun and a sky
# light the scene.
import argparse
import math
import sys

import bpy
import numpy
from mathutils import Vector

# Debian 12's Blender 3.4 glTF importer still uses numpy.bool (removed in numpy 1.24)
if not hasattr(numpy, "bool"):
    numpy.bool = bool

parser = argparse.ArgumentParser(prog="blender_render.py")
parser.add_argument("glb")
parser.add_argument("png")
parser.add_argument("--time", type=float, default=0.0, help="seconds into the animation")
parser.add_argument("--size", default="640x360")
parser.add_argument("--samples", type=int, default=16)
args = parser.parse_args(sys.argv[sys.argv.index("--") + 1:])
width, height = (int(v) for v in args.size.split("x"))

bpy.ops.wm.read_factory_settings(use_empty=True)
scene = bpy.context.scene
scene.render.fps = 30
bpy.ops.import_scene.gltf(filepath=args.glb)
scene.frame_set(int(round(args.time * 30)))

pelvis = scene.objects.get("pelvis")
target = pelvis.matrix_world.translation.copy() if pelvis else Vector((0, 0, 0.8))
target.z = max(target.z, 0.7)
facing = pelvis.matrix_world.to_3x3() @ Vector((1, 0, 0)) if pelvis else Vector((1, 0, 0))
heading = math.atan2(facing.y, facing.x) + math.radians(35)
eye = target + Vector((3.5 * math.cos(heading), 3.5 * math.sin(heading), 1.2))

cam_data = bpy.data.cameras.new("camera")
cam_data.lens = 35
cam = bpy.data.objects.new("camera", cam_data)
scene.collection.objects.link(cam)
cam.location = eye
cam.rotation_euler = (target - eye).to_track_quat("-Z", "Y").to_euler()
scene.camera = cam

sun_data = bpy.data.lights.new("sun", type="SUN")
sun_data.energy = 1.5
sun_data.angle = math.radians(10)
sun = bpy.data.objects.new("sun", sun_data)
sun.rotation_euler = (math.radians(40), math.radians(15), math.radians(30))
scene.collection.objects.link(sun)
world = bpy.data.worlds.new("sky")
world.use_nodes = True
world.node_tree.nodes["Background"].inputs[0].default_value = (0.62, 0.74, 0.88, 1.0)
world.node_tree.nodes["Background"].inputs[1].default_value = 0.35
scene.world = world

scene.view_settings.exposure = -0.5
scene.render.engine = "CYCLES"
scene.cycles.device = "CPU"
scene.cycles.samples = args.samples
scene.cycles.use_denoising = False  # Debian builds Blender without OpenImageDenoise
scene.render.resolution_x = width
scene.render.resolution_y = height
scene.render.resolution_percentage = 100
scene.render.filepath = args.png
scene.render.image_settings.file_format = "PNG"
bpy.ops.render.render(write_still=True)
print("rendered", args.png, flush=True)
