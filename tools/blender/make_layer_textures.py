# Makes the layer-textures scene, as a user paints where a varnish and a shine go in Blender: three
# dark matte 1.6 m planes side by side under a low sun shining towards the camera, so that the
# camera looks into their reflections.
#   - "coat": a Principled BSDF whose Clearcoat input is a black/white checker through a Separate
#     RGB node (coat roughness 0.25): the exporter writes KHR_materials_clearcoat's
#     clearcoatTexture.
#   - "shine": whose Specular input is the same checker: the exporter bakes it into
#     KHR_materials_specular's specularColorTexture (with a specularColorFactor above 1 and
#     KHR_materials_ior 1.45).
#   - "cloth": plain; Blender 3.4's exporter writes no sheen from a Principled BSDF, so the test
#     gives this one its sheen texture itself (the checker as sheenColorTexture).
#   - "ridges", behind "shine": a clear coat (roughness 0.2) whose Clearcoat Normal is a Normal Map
#     node reading a 2×2 checker of normals tilted 25° to +v and to −v: the exporter writes
#     KHR_materials_clearcoat's clearcoatNormalTexture.
#
#   tools/install-deps.sh --scene-tools
#   blender -b --factory-startup --python tools/blender/make_layer_textures.py -- [OUT_DIR]
#
# Writes OUT_DIR (default tests/data/blender/layer_textures): layer_textures.gltf + .bin and the
# images (the sun: KHR_lights_punctual, 683 lm/W).

import math
import os
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from scene_parts import (  # noqa: E402  (this folder, put on the path above)
    black_world, build_and_export, checker_image, enable_gltf_exporter, hard_sun, principled, scene_camera)

enable_gltf_exporter()

WIDTH, HEIGHT = 160, 90
BLACK, WHITE = (0.0, 0.0, 0.0, 1.0), (1.0, 1.0, 1.0, 1.0)
DARK = (0.05, 0.05, 0.05)


def arguments():
    args = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    return os.path.abspath(args[0] if args else "tests/data/blender/layer_textures")


def checker_into(material, image, socket):
    """The image's red channel (Closest) into the Principled BSDF's `socket` through a Separate RGB
    node: the exporter's documented layout for a single-channel input."""
    nodes, links = material.node_tree.nodes, material.node_tree.links
    tex = nodes.new("ShaderNodeTexImage")
    tex.image = image
    tex.interpolation = "Closest"
    separate = nodes.new("ShaderNodeSeparateRGB")
    links.new(tex.outputs["Color"], separate.inputs["Image"])
    links.new(separate.outputs["R"], nodes["Principled BSDF"].inputs[socket])


def plane(name, x, material, y=0.0):
    bpy.ops.mesh.primitive_plane_add(size=1.6, location=(x, y, 0.0))
    obj = bpy.context.object
    obj.name = obj.data.name = name
    obj.data.materials.append(material)


def build(folder):
    # Rows bottom-up: white, black / black, white; Non-Color data.
    image = checker_image(folder, "layer_checker", WHITE, BLACK, is_data=True)
    coat = principled("coat", DARK, roughness=0.9)
    bsdf = coat.node_tree.nodes["Principled BSDF"]
    bsdf.inputs["Clearcoat"].default_value = 1.0
    bsdf.inputs["Clearcoat Roughness"].default_value = 0.25
    checker_into(coat, image, "Clearcoat")
    plane("coat", -1.8, coat)

    shine = principled("shine", DARK, roughness=0.3)
    checker_into(shine, image, "Specular")
    plane("shine", 0.0, shine)

    plane("cloth", 1.8, principled("cloth", DARK, roughness=0.9))

    # Tangent-space normals (0, sin 25°, cos 25°) and (0, −sin 25°, cos 25°), encoded n/2 + ½:
    # tilted towards the sun and away from it.
    tilt = math.radians(25.0)
    up = (0.5, 0.5 + 0.5 * math.sin(tilt), 0.5 + 0.5 * math.cos(tilt), 1.0)
    down = (0.5, 0.5 - 0.5 * math.sin(tilt), 0.5 + 0.5 * math.cos(tilt), 1.0)
    normals = checker_image(folder, "ridge_normals", up, down, is_data=True)
    ridges = principled("ridges", DARK, roughness=0.9)
    nodes, links = ridges.node_tree.nodes, ridges.node_tree.links
    bsdf = nodes["Principled BSDF"]
    bsdf.inputs["Clearcoat"].default_value = 1.0
    bsdf.inputs["Clearcoat Roughness"].default_value = 0.2
    tex = nodes.new("ShaderNodeTexImage")
    tex.image = normals
    tex.interpolation = "Closest"
    normal_map = nodes.new("ShaderNodeNormalMap")
    links.new(tex.outputs["Color"], normal_map.inputs["Color"])
    links.new(normal_map.outputs["Normal"], bsdf.inputs["Clearcoat Normal"])
    plane("ridges", 0.0, ridges, y=2.0)


def add_lights():
    # 3 W/m², 30° above the horizon, travelling towards −y (towards the camera).
    hard_sun(3.0, 30.0, 180.0)


def add_camera():
    scene_camera((0.0, -4.2, 2.2), (0.0, 0.2, 0.0), 60.0, WIDTH, HEIGHT)


def main():
    folder = arguments()
    os.makedirs(folder, exist_ok=True)
    build_and_export(folder, "layer_textures", lambda: build(folder), add_lights, add_camera, black_world)


main()
