# Makes Lit's Blender test scenes: builds each scene in Blender, exports it with Blender's own
# glTF exporter (default "Standard" lighting mode: photometric cd / lux at 683 lm/W) and renders
# it with Cycles for reference numbers.
#
#   tools/install-deps.sh --scene-tools     # blender and python3-numpy (the glTF exporter needs numpy)
#   blender -b --factory-startup --python tools/blender/make_scenes.py -- OUT_DIR
#
# Writes OUT_DIR/<scene>.gltf + .bin, OUT_DIR/<scene>_cycles.png (Standard view transform, for
# eyes) and OUT_DIR/cycles_reference.json with the linear mean of each Cycles render (read back
# from an OpenEXR of the render, so no view transform or sRGB curve is involved) and how it was
# made, also of a render with no bounces (direct light only). tests/gl/test_scene_defaults.cpp
# compares Lit's linear HDR means with those numbers.
#
# The scenes: an open room (floor, back wall, red left wall, a box and a sphere), black world,
# hard shadows (light radius 0), lit by one light each:
#   point  500 W point light; the camera has an animation "fly" (3 s, 4 keyframes)
#   spot   800 W spot light, 70° cone, blend 0.15
#   sun    sun of 3 W/m², 50° above the horizon
# Blender 3.4 (Debian's), Cycles on the CPU, 128 x 128 pixels, 256 samples, no denoising.

import json
import math
import os
import sys

import bpy
from mathutils import Vector

try:
    import numpy  # noqa: F401  (Blender's glTF exporter imports it; fail here with the fix, not mid-export)
except ImportError:
    sys.exit("make_scenes.py: Blender's glTF exporter needs numpy: run tools/install-deps.sh --scene-tools "
             "(Debian: apt-get install python3-numpy)")

SIZE = 128
SAMPLES = 256


def out_dir():
    args = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    return os.path.abspath(args[0] if args else "tests/data/blender")


def material(name, color, roughness=0.6):
    m = bpy.data.materials.new(name)
    m.use_nodes = True
    bsdf = m.node_tree.nodes["Principled BSDF"]
    bsdf.inputs["Base Color"].default_value = (*color, 1.0)
    bsdf.inputs["Roughness"].default_value = roughness
    bsdf.inputs["Specular"].default_value = 0.5  # F0 = 0.04, as glTF's dielectric
    return m


def add(obj, mat):
    obj.data.materials.append(mat)
    return obj


def build_room():
    white = material("white", (0.8, 0.8, 0.8))
    red = material("red", (0.7, 0.12, 0.1))
    blue = material("blue", (0.15, 0.25, 0.7), roughness=0.4)
    bpy.ops.mesh.primitive_plane_add(size=6, location=(0, 0, 0))
    add(bpy.context.object, white).name = "floor"
    bpy.ops.mesh.primitive_plane_add(size=6, location=(0, 3, 3), rotation=(math.radians(90), 0, 0))
    add(bpy.context.object, white).name = "back_wall"
    bpy.ops.mesh.primitive_plane_add(size=6, location=(-3, 0, 3), rotation=(0, math.radians(90), 0))
    add(bpy.context.object, red).name = "left_wall"
    bpy.ops.mesh.primitive_cube_add(size=1.2, location=(-0.8, 0.6, 0.6), rotation=(0, 0, math.radians(20)))
    box = add(bpy.context.object, white)
    box.name = "box"
    box["litTest"] = "kept by a save"  # exported as node extras (export_extras)
    bpy.ops.mesh.primitive_uv_sphere_add(radius=0.6, location=(1.0, -0.2, 0.6), segments=32, ring_count=16)
    sphere = add(bpy.context.object, blue)
    sphere.name = "sphere"
    bpy.ops.object.shade_smooth()


def add_camera(animated):
    bpy.ops.object.camera_add(location=(0.6, -6.5, 3.2))
    cam = bpy.context.object
    cam.name = "camera"
    cam.data.lens_unit = "FOV"
    cam.data.angle = math.radians(55)
    direction = Vector((0.0, 0.5, 1.0)) - cam.location
    cam.rotation_euler = direction.to_track_quat("-Z", "Y").to_euler()
    bpy.context.scene.camera = cam
    if animated:
        scene = bpy.context.scene
        scene.render.fps = 24
        keys = [(1, (0.6, -6.5, 3.2)), (25, (2.5, -5.0, 2.5)), (49, (3.5, -2.0, 2.0)), (73, (1.0, -4.0, 1.5))]
        for frame, location in keys:
            cam.location = location
            direction = Vector((0.0, 0.5, 1.0)) - cam.location
            cam.rotation_euler = direction.to_track_quat("-Z", "Y").to_euler()
            cam.keyframe_insert("location", frame=frame)
            cam.keyframe_insert("rotation_euler", frame=frame)
        cam.animation_data.action.name = "fly"
        scene.frame_start, scene.frame_end = 1, 73
        scene.frame_set(1)
    return cam


def add_light(kind):
    if kind == "point":
        bpy.ops.object.light_add(type="POINT", location=(0.5, -0.5, 3.0))
        light = bpy.context.object
        light.data.energy = 500.0  # W
    elif kind == "spot":
        bpy.ops.object.light_add(type="SPOT", location=(1.5, -2.0, 3.5))
        light = bpy.context.object
        light.data.energy = 800.0  # W, as if a point light (Blender's convention)
        light.data.spot_size = math.radians(70)
        light.data.spot_blend = 0.15
        direction = Vector((0.0, 0.5, 0.0)) - light.location
        light.rotation_euler = direction.to_track_quat("-Z", "Y").to_euler()
    else:
        bpy.ops.object.light_add(type="SUN", location=(0, 0, 5))
        light = bpy.context.object
        light.data.energy = 3.0  # W/m²
        light.data.angle = 0.0
        light.rotation_euler = (math.radians(40), 0.0, math.radians(35))  # 50° above the horizon
    light.name = kind + "_light"
    light.data.shadow_soft_size = 0.0  # hard shadows, as Lit's punctual lights
    return light


def setup_render():
    scene = bpy.context.scene
    scene.render.engine = "CYCLES"
    scene.cycles.device = "CPU"
    scene.cycles.samples = SAMPLES
    scene.cycles.use_denoising = False
    scene.cycles.seed = 1
    scene.render.resolution_x = SIZE
    scene.render.resolution_y = SIZE
    scene.render.resolution_percentage = 100
    scene.render.film_transparent = False
    scene.view_settings.view_transform = "Standard"
    scene.view_settings.look = "None"
    scene.view_settings.exposure = 0.0
    scene.view_settings.gamma = 1.0
    world = bpy.data.worlds.new("black") if not scene.world else scene.world
    scene.world = world
    world.use_nodes = True
    world.node_tree.nodes["Background"].inputs["Color"].default_value = (0, 0, 0, 1)
    world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.0


def exr_mean(path_exr):
    image = bpy.data.images.load(path_exr)
    pixels = list(image.pixels)
    n = len(pixels) // 4
    mean = [sum(pixels[c::4]) / n for c in range(3)]
    bpy.data.images.remove(image)
    os.remove(path_exr)
    return mean


def render_direct_mean(path_exr):
    # Light that reaches the camera after one surface only (Cycles with no bounces): Lit's
    # direct terms, to tell the light units apart from the GI.
    scene = bpy.context.scene
    bounces = scene.cycles.max_bounces
    scene.cycles.max_bounces = 0
    scene.render.image_settings.file_format = "OPEN_EXR"
    scene.render.image_settings.color_depth = "32"
    scene.render.filepath = path_exr
    bpy.ops.render.render(write_still=True)
    scene.cycles.max_bounces = bounces
    return exr_mean(path_exr)


def render_mean(path_png, path_exr):
    scene = bpy.context.scene
    scene.render.image_settings.file_format = "OPEN_EXR"
    scene.render.image_settings.color_depth = "32"
    scene.render.filepath = path_exr
    bpy.ops.render.render(write_still=True)
    mean = exr_mean(path_exr)
    scene.render.image_settings.file_format = "PNG"
    scene.render.image_settings.color_depth = "8"
    scene.render.filepath = path_png
    bpy.ops.render.render(write_still=True)
    return mean


def make(kind, folder):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    build_room()
    add_camera(animated=(kind == "point"))
    add_light(kind)
    setup_render()
    gltf = os.path.join(folder, kind + ".gltf")
    bpy.ops.export_scene.gltf(filepath=gltf, export_format="GLTF_SEPARATE", export_lights=True,
                              export_cameras=True, export_extras=True, export_apply=True)
    mean = render_mean(os.path.join(folder, kind + "_cycles.png"), os.path.join(folder, kind + "_cycles.exr"))
    direct = render_direct_mean(os.path.join(folder, kind + "_cycles_direct.exr"))
    def luminance(rgb):
        return 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2]
    return {"meanRgb": mean, "meanLuminance": luminance(mean),
            "directMeanRgb": direct, "directMeanLuminance": luminance(direct)}


def main():
    folder = out_dir()
    os.makedirs(folder, exist_ok=True)
    results = {}
    for kind in ("point", "spot", "sun"):
        results[kind] = make(kind, folder)
    info = {
        "made": "blender -b --factory-startup --python tools/blender/make_scenes.py -- " + os.path.relpath(folder),
        "blender": bpy.app.version_string,
        "cycles": {"samples": SAMPLES, "size": [SIZE, SIZE], "denoising": False, "device": "CPU",
                   "bounces": "Blender defaults (max 12, diffuse 4, glossy 4); direct*: max bounces 0"},
        "viewTransform": "Standard, look None, exposure 0, gamma 1 (the PNGs); the means are of the linear "
                         "OpenEXR render (scene-linear radiance, no view transform), all pixels, world black",
        "gltfExport": "Blender glTF exporter, default lighting mode (Standard: W -> cd as W/(4 pi) x 683, "
                      "sun W/m^2 -> lux x 683), lights, cameras and extras exported",
        "scenes": results,
    }
    with open(os.path.join(folder, "cycles_reference.json"), "w") as f:
        json.dump(info, f, indent=2)
        f.write("\n")
    print("wrote", folder, json.dumps(results))


main()
