# Makes the texture-transform test scene: two planes seen from above, each with a red/blue checker
# (a 2×2 image, Closest interpolation) placed by a Mapping node, as a user tiles a texture in
# Blender. The exporter writes the Mapping node as KHR_texture_transform on the base colour and
# emissive textures (the image drives both, so the planes show their texture without lights).
#
#   tools/install-deps.sh --scene-tools
#   blender -b --factory-startup --python tools/blender/make_texture_transform.py -- [OUT_DIR]
#
# Writes OUT_DIR (default tests/data/blender/texture_transform):
#   texture_transform.gltf + .bin   the Mapping nodes as exported (KHR_texture_transform)
#   texture_transform_baked.gltf    the same scene with each Mapping node applied to the mesh's
#                                   UVs by this script and removed: what the first must look like
#   checker.png                     the texture both use
# The left plane's Mapping is scale (3, 2) and location (0.25, 0): a row across it crosses six
# checker edges (u from 0.25 to 3.25, an edge every 0.5). The right plane's adds a 30° rotation.

import os
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from scene_parts import (  # noqa: E402  (this folder, put on the path above)
    bake_mapping, build_and_export_twins, checker_image, enable_gltf_exporter, mapped_image, two_planes_camera)

enable_gltf_exporter()

WIDTH, HEIGHT = 256, 128
RED, BLUE = (1.0, 0.0, 0.0, 1.0), (0.0, 0.0, 1.0, 1.0)
# Each plane's Mapping node (Point type): location (u, v), rotation about Z (degrees), scale (u, v).
MAPPINGS = {
    "left": ((0.25, 0.0), 0.0, (3.0, 2.0)),
    "right": ((0.1, 0.2), 30.0, (2.0, 2.0)),
}


def arguments():
    args = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    return os.path.abspath(args[0] if args else "tests/data/blender/texture_transform")


def checker(folder):
    # Rows bottom-up: red, blue / blue, red.
    return checker_image(folder, "checker", RED, BLUE)


def material(name, image, mapping):
    m = bpy.data.materials.new(name)
    m.use_nodes = True
    bsdf = m.node_tree.nodes["Principled BSDF"]
    bsdf.inputs["Roughness"].default_value = 1.0
    bsdf.inputs["Emission Strength"].default_value = 1.0
    tex = mapped_image(m, image, mapping)
    m.node_tree.links.new(tex.outputs["Color"], bsdf.inputs["Base Color"])
    m.node_tree.links.new(tex.outputs["Color"], bsdf.inputs["Emission"])
    return m


def build(image):
    for name, x in (("left", -1.1), ("right", 1.1)):
        bpy.ops.mesh.primitive_plane_add(size=2.0, location=(x, 0.0, 0.0))
        plane = bpy.context.object
        plane.name = name
        plane.data.materials.append(material("checker_" + name, image, MAPPINGS[name]))
    two_planes_camera(WIDTH, HEIGHT)


def bake_mappings():
    """Applies each Mapping node to its plane's UVs and removes it."""
    for name, mapping in MAPPINGS.items():
        bake_mapping(bpy.data.objects[name], mapping)


def main():
    folder = arguments()
    build_and_export_twins(folder, "texture_transform", lambda: build(checker(folder)), bake_mappings)


main()
