# Makes the sun room: a closed room with 0.3 m thick walls, lit only by a low sun through one
# window, so that most of what the camera sees is lit by bounced light. Made as a user makes a
# room in Blender (cubes, a Principled BSDF per material, a sun lamp), exported with Blender's glTF
# exporter, and rendered with Cycles with every bounce (max bounces 128) for reference.
#
#   tools/install-deps.sh --scene-tools
#   blender -b --factory-startup --python tools/blender/make_sun_room.py -- OUT_DIR [SAMPLES]
#
# Writes OUT_DIR/sun_room.gltf + .bin and two Cycles renders as Radiance HDR (linear, no view
# transform), which `lit-render --compare` and tools/room-accuracy.sh read:
#   sun_room_cycles.hdr          the materials as exported (Principled BSDF)
#   sun_room_cycles_diffuse.hdr  every material a pure Diffuse BSDF of the same colour (the gold
#                                sphere too): tells Blender's Principled diffuse from Lambert
# and sun_room_cycles.json saying how they were made.

import json
import math
import os
import sys

import bpy
from mathutils import Vector

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from scene_parts import box, cycles_on_cpu, enable_gltf_exporter, principled  # noqa: E402  (this folder, put on the path above)

enable_gltf_exporter()

WIDTH, HEIGHT = 160, 100


def arguments():
    args = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    folder = os.path.abspath(args[0] if args else "tests/data/blender/sun_room")
    samples = int(args[1]) if len(args) > 1 else 4096
    return folder, samples


def material(name, color, roughness=0.8, metallic=0.0):
    """principled(), remembering its colour for the pure Diffuse BSDF variant."""
    m = principled(name, color, roughness, metallic)
    m["litColor"] = list(color)  # for the diffuse variant
    return m


def build():
    white = material("white_plaster", (0.8, 0.8, 0.8))
    floor = material("floor", (0.55, 0.5, 0.45), roughness=0.7)
    blue = material("blue_paint", (0.1, 0.2, 0.65), roughness=0.5)
    gold = material("gold", (1.0, 0.77, 0.34), roughness=0.35, metallic=1.0)
    t = 0.3  # wall thickness, m
    # Inside: x in [-3, 3], y in [-2, 2], z in [0, 3]; the window in the wall at y = +2.
    box("floor", (-3 - t, -2 - t, -t), (3 + t, 2 + t, 0), floor)
    box("ceiling", (-3 - t, -2 - t, 3), (3 + t, 2 + t, 3 + t), white)
    box("wall_west", (-3 - t, -2, 0), (-3, 2, 3), white)
    box("wall_east", (3, -2, 0), (3 + t, 2, 3), white)
    box("wall_south", (-3 - t, -2 - t, 0), (3 + t, -2, 3), white)
    # The window wall around a 1.2 m × 1.2 m opening, x in [0.2, 1.4], z in [1.0, 2.2].
    box("wall_north_left", (-3 - t, 2, 0), (0.2, 2 + t, 3), white)
    box("wall_north_right", (1.4, 2, 0), (3 + t, 2 + t, 3), white)
    box("wall_north_below", (0.2, 2, 0), (1.4, 2 + t, 1.0), white)
    box("wall_north_above", (0.2, 2, 2.2), (1.4, 2 + t, 3), white)
    box("white_block", (-1.8, 0.2, 0), (-0.9, 1.1, 0.9), white)
    box("blue_box", (1.6, -1.4, 0), (2.3, -0.7, 0.7), blue)
    bpy.ops.mesh.primitive_uv_sphere_add(radius=0.45, location=(-0.2, -0.7, 0.45), segments=48, ring_count=24)
    sphere = bpy.context.object
    sphere.name = "gold_sphere"
    sphere.data.materials.append(gold)
    bpy.ops.object.shade_smooth()


def add_sun():
    bpy.ops.object.light_add(type="SUN", location=(0.8, 4.0, 4.0))
    sun = bpy.context.object
    sun.name = "sun"
    sun.data.energy = 5.0  # W/m² (the exporter writes 5 × 683 lux)
    sun.data.angle = 0.0   # hard shadows, as Lit's directional light
    # 30° above the horizon, coming in through the window towards -y, a little from the east.
    elevation, azimuth = math.radians(30), math.radians(15)
    direction = Vector((-math.sin(azimuth) * math.cos(elevation), -math.cos(azimuth) * math.cos(elevation),
                        -math.sin(elevation)))
    sun.rotation_euler = direction.to_track_quat("-Z", "Y").to_euler()


def add_camera():
    bpy.ops.object.camera_add(location=(-2.6, -1.7, 1.7))
    cam = bpy.context.object
    cam.name = "camera"
    cam.data.lens_unit = "FOV"
    cam.data.angle = math.radians(75)
    direction = Vector((1.2, 1.2, 0.9)) - cam.location
    cam.rotation_euler = direction.to_track_quat("-Z", "Y").to_euler()
    bpy.context.scene.camera = cam


def setup_cycles(samples):
    scene = cycles_on_cpu(samples)
    # Every bounce, as Lit's default and its reference's --bounces all (Blender's default stops
    # diffuse light after 4).
    scene.cycles.max_bounces = 128
    scene.cycles.diffuse_bounces = 128
    scene.cycles.glossy_bounces = 128
    scene.cycles.sample_clamp_direct = 0.0
    scene.cycles.sample_clamp_indirect = 0.0
    scene.cycles.caustics_reflective = True
    scene.render.resolution_x = WIDTH
    scene.render.resolution_y = HEIGHT
    scene.render.resolution_percentage = 100
    world = bpy.data.worlds.new("black")
    scene.world = world
    world.use_nodes = True
    world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.0
    scene.render.image_settings.file_format = "HDR"


def render(path):
    bpy.context.scene.render.filepath = path
    bpy.ops.render.render(write_still=True)


def to_diffuse():
    for m in bpy.data.materials:
        if "litColor" not in m:
            continue
        nodes = m.node_tree.nodes
        output = nodes["Material Output"]
        diffuse = nodes.new("ShaderNodeBsdfDiffuse")
        diffuse.inputs["Color"].default_value = (*m["litColor"], 1.0)
        diffuse.inputs["Roughness"].default_value = 0.0  # Lambert
        m.node_tree.links.new(diffuse.outputs["BSDF"], output.inputs["Surface"])


def main():
    folder, samples = arguments()
    os.makedirs(folder, exist_ok=True)
    bpy.ops.wm.read_factory_settings(use_empty=True)
    build()
    add_sun()
    add_camera()
    setup_cycles(samples)
    bpy.ops.export_scene.gltf(filepath=os.path.join(folder, "sun_room.gltf"), export_format="GLTF_SEPARATE",
                              export_lights=True, export_cameras=True, export_apply=True)
    render(os.path.join(folder, "sun_room_cycles.hdr"))
    to_diffuse()
    render(os.path.join(folder, "sun_room_cycles_diffuse.hdr"))
    info = {
        "made": "blender -b --factory-startup --python tools/blender/make_sun_room.py -- " + os.path.relpath(folder)
        + " " + str(samples),
        "blender": bpy.app.version_string,
        "cycles": {"samples": samples, "size": [WIDTH, HEIGHT], "denoising": False, "device": "CPU",
                   "bounces": "max 128, diffuse 128, glossy 128, no clamping", "world": "black"},
        "images": {"sun_room_cycles.hdr": "materials as exported (Principled BSDF)",
                   "sun_room_cycles_diffuse.hdr": "every material a Diffuse BSDF (roughness 0: Lambert) of the "
                                                  "same base colour"},
    }
    with open(os.path.join(folder, "sun_room_cycles.json"), "w") as f:
        json.dump(info, f, indent=2)
        f.write("\n")


main()
