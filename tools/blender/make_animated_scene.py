# Makes the animated scene: a red box that slides across a floor and a blue door that swings open
# on its hinge, keyframed in Blender as a user keys them (location and rotation keys, linear
# interpolation), exported with Blender's glTF exporter. The node-animation tests render it at
# known times and look for each object where its keys put it.
#
#   tools/install-deps.sh --scene-tools
#   blender -b --factory-startup --python tools/blender/make_animated_scene.py -- OUT_DIR
#
# Writes OUT_DIR/animated.gltf + .bin. Positions in glTF axes (+Y up; Blender's (x, y, z) is
# glTF's (x, z, −y)); 24 frames per second, keys at frames 0 and 48 (the exporter writes frame f at
# f / 24 s, so frame 0 is 0 s):
#   box     0.6 m cube, centre (−1.5, 0.3, 0) at 0 s → (+1.5, 0.3, 0) at 2 s, linear in between
#   door    1.0 m × 2.0 m × 0.1 m, hinge at (−2.5, 0, −1.5), closed along +X at 0 s, turned 90° about
#           +Y at 2 s so it stands edge-on to the camera (its free edge towards −Z)
#   camera  at (0, 1.5, 6) looking down −Z, vertical field of view 40°, aspect 1.6
#   floor   8 m × 8 m at y 0; a back wall at z −4; a sun from above and in front

import math
import os
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from scene_parts import box, enable_gltf_exporter, principled  # noqa: E402  (this folder, put on the path above)

enable_gltf_exporter()

FPS = 24
END_FRAME = 2 * FPS  # 2 s


def arguments():
    args = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    return os.path.abspath(args[0] if args else "tests/data/blender/animated")


def linear_keys(obj):
    # Blender keys with Bézier easing by default; linear keys make the positions between keys
    # easy to state (and the exporter samples them into LINEAR glTF keys either way).
    for curve in obj.animation_data.action.fcurves:
        for point in curve.keyframe_points:
            point.interpolation = "LINEAR"


def build():
    grey = principled("floor", (0.5, 0.5, 0.5))
    white = principled("wall", (0.8, 0.8, 0.8))
    red = principled("red", (0.8, 0.05, 0.05), roughness=0.6)
    blue = principled("blue", (0.05, 0.15, 0.8), roughness=0.6)
    box("floor", (-4, -4, -0.1), (4, 4, 0), grey)
    box("back_wall", (-4, 4, 0), (4, 4.1, 4), white)

    # The box: keyed at frames 0 and 48, Blender x −1.5 → +1.5.
    cube = box("box", (-0.3, -0.3, 0.0), (0.3, 0.3, 0.6), red)
    bpy.ops.object.origin_set(type="ORIGIN_GEOMETRY", center="BOUNDS")
    cube.location = (-1.5, 0.0, 0.3)
    cube.keyframe_insert("location", frame=0)
    cube.location = (1.5, 0.0, 0.3)
    cube.keyframe_insert("location", frame=END_FRAME)
    linear_keys(cube)

    # The door: origin on its hinge (Blender (−2.5, 1.5, 0)), the panel along +X from there.
    door = box("door", (-2.5, 1.45, 0.0), (-1.5, 1.55, 2.0), blue)
    bpy.context.scene.cursor.location = (-2.5, 1.5, 0.0)
    bpy.ops.object.origin_set(type="ORIGIN_CURSOR")
    door.rotation_mode = "XYZ"
    door.rotation_euler = (0.0, 0.0, 0.0)
    door.keyframe_insert("rotation_euler", frame=0)
    door.rotation_euler = (0.0, 0.0, math.radians(90.0))  # free edge swings to Blender +Y, away from the camera
    door.keyframe_insert("rotation_euler", frame=END_FRAME)
    linear_keys(door)

    bpy.ops.object.light_add(type="SUN", location=(0.0, -3.0, 6.0))
    sun = bpy.context.object
    sun.name = "sun"
    sun.data.energy = 3.0  # W/m²
    sun.data.angle = 0.0
    sun.rotation_euler = (math.radians(30.0), 0.0, math.radians(20.0))

    bpy.ops.object.camera_add(location=(0.0, -6.0, 1.5), rotation=(math.radians(90.0), 0.0, 0.0))
    cam = bpy.context.object
    cam.name = "camera"
    cam.data.sensor_fit = "VERTICAL"
    cam.data.angle = math.radians(40.0)
    bpy.context.scene.camera = cam

    scene = bpy.context.scene
    scene.render.fps = FPS
    scene.frame_start = 0
    scene.frame_end = END_FRAME
    scene.render.resolution_x = 320
    scene.render.resolution_y = 200


def main():
    folder = arguments()
    os.makedirs(folder, exist_ok=True)
    bpy.ops.wm.read_factory_settings(use_empty=True)
    build()
    bpy.ops.export_scene.gltf(filepath=os.path.join(folder, "animated.gltf"), export_format="GLTF_SEPARATE",
                              export_lights=True, export_cameras=True, export_apply=True, export_animations=True)


main()
