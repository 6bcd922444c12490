# Imports a .glb and a .bvh into Blender (run headless by export_test.cc):
#   blender -b --python blender_check.py -- scene.glb motion.bvh
# and prints one line per file with what Blender made of it:
#   GLB objects <n> meshes <n> actions <n> frames <first> <last>   (at 30 frames per second)
#   BVH armatures <n> bones <n> frames <first> <last>
import builtins
import sys

import bpy
import numpy

# Debian 12's Blender 3.4 meets Debian 12's Python 3.11 and numpy 1.24: its glTF importer
# still uses numpy.bool and its BVH importer opens files with mode 'rU' (both removed)
if not hasattr(numpy, "bool"):
    numpy.bool = bool
_open = builtins.open


def _open_without_u(file, mode="r", *args, **kwargs):
    return _open(file, mode.replace("U", ""), *args, **kwargs)


builtins.open = _open_without_u

glb, bvh = sys.argv[sys.argv.index("--") + 1:]
bpy.ops.wm.read_factory_settings(use_empty=True)
bpy.context.scene.render.fps = 30  # keyframes at time x 30
bpy.ops.import_scene.gltf(filepath=glb)
objects = list(bpy.context.scene.objects)
meshes = [o for o in objects if o.type == "MESH"]
actions = list(bpy.data.actions)
first = min((a.frame_range[0] for a in actions), default=0)
last = max((a.frame_range[1] for a in actions), default=0)
print(f"GLB objects {len(objects)} meshes {len(meshes)} actions {len(actions)} "
      f"frames {first:g} {last:g}", flush=True)
pelvis = bpy.context.scene.objects.get("pelvis")
if pelvis is not None:
    bpy.context.scene.frame_set(0)
    p = pelvis.matrix_world.translation
    print(f"GLB pelvis {p.x:.4f} {p.y:.4f} {p.z:.4f}", flush=True)

bpy.ops.wm.read_factory_settings(use_empty=True)
bpy.ops.import_anim.bvh(filepath=bvh)
arms = [o for o in bpy.context.scene.objects if o.type == "ARMATURE"]
bones = len(arms[0].data.bones) if arms else 0
rng = arms[0].animation_data.action.frame_range if arms else (0, 0)
print(f"BVH armatures {len(arms)} bones {bones} frames {rng[0]:g} {rng[1]:g}", flush=True)
