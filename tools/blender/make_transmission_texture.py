# Makes the transmission-texture scene, as a user paints where a glass lets light through in
# Blender: a Principled BSDF whose Transmission input is driven by an image (a 2×2 black/white
# checker, Closest interpolation), which the glTF exporter writes as
# KHR_materials_transmission's transmissionTexture. A 2 × 2 m pane hangs flat 1.2 m above a
# matte grey floor under a high sun (black world): its clear quadrants let the sun through, its
# opaque ones (white, matte where Transmission is 0) shadow the floor, so the floor shows the
# checker in light and shadow. The camera looks down from the front: it sees the pane's sunlit top
# (white where opaque, the floor through it where clear) and, past the pane's near edge, the floor
# beneath it.
#
#   tools/install-deps.sh --scene-tools
#   blender -b --factory-startup --python tools/blender/make_transmission_texture.py -- [OUT_DIR]
#
# Writes OUT_DIR (default tests/data/blender/transmission_texture): transmission_texture.gltf +
# .bin and the exported image (the sun: KHR_lights_punctual, 683 lm/W).

import os
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from scene_parts import (  # noqa: E402  (this folder, put on the path above)
    black_world, build_and_export, checker_image, enable_gltf_exporter, floor_plane, hard_sun, principled,
    scene_camera)

enable_gltf_exporter()

WIDTH, HEIGHT = 160, 90
BLACK, WHITE = (0.0, 0.0, 0.0, 1.0), (1.0, 1.0, 1.0, 1.0)


def arguments():
    args = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    return os.path.abspath(args[0] if args else "tests/data/blender/transmission_texture")


def checker_glass(folder):
    """White glass, roughness 0, IOR 1.5, whose Transmission is a black/white checker."""
    # Rows bottom-up: white, black / black, white; Non-Color data.
    image = checker_image(folder, "transmission_checker", WHITE, BLACK, is_data=True)
    m = principled("pane", (1.0, 1.0, 1.0), roughness=0.0)
    nodes, links = m.node_tree.nodes, m.node_tree.links
    bsdf = nodes["Principled BSDF"]
    bsdf.inputs["IOR"].default_value = 1.5
    bsdf.inputs["Transmission"].default_value = 1.0
    tex = nodes.new("ShaderNodeTexImage")
    tex.image = image
    tex.interpolation = "Closest"
    # The exporter's documented layout for a single-channel input: the image's red channel
    # through a Separate RGB node.
    separate = nodes.new("ShaderNodeSeparateRGB")
    links.new(tex.outputs["Color"], separate.inputs["Image"])
    links.new(separate.outputs["R"], bsdf.inputs["Transmission"])
    return m


def build(folder):
    floor_plane(8.0, 8.0, principled("floor", (0.5, 0.5, 0.5), roughness=0.9))
    bpy.ops.mesh.primitive_plane_add(size=2.0, location=(0.0, 0.0, 1.2))
    pane = bpy.context.object
    pane.name = pane.data.name = "pane"
    pane.data.materials.append(checker_glass(folder))


def add_lights():
    # 3 W/m², hard shadows, 65° above the horizon, travelling towards +y: the pane's shadow falls
    # 0.56 m beyond its footprint, towards the camera's far side.
    hard_sun(3.0, 65.0, 0.0)


def add_camera():
    scene_camera((0.0, -4.5, 3.0), (0.0, 0.3, 0.6), 60.0, WIDTH, HEIGHT)


def main():
    folder = arguments()
    os.makedirs(folder, exist_ok=True)
    build_and_export(folder, "transmission_texture", lambda: build(folder), add_lights, add_camera, black_world)


main()
