# Makes the second-UV-set test scene: two planes seen from above, each with two UV maps, as a user
# lays out a detail or lightmap set beside the default one. The left plane's red/blue checker (a
# 2×2 image, Closest interpolation) is sampled through a UV Map node that picks its second map,
# "Detail" (the default map scaled 3 × 2 and moved 0.25 along u): Blender's exporter writes
# TEXCOORD_1 and a texCoord of 1 on the base colour and emissive textures. The right plane's
# checker reads its first map; its second (turned 30°) is exported and unused.
#
#   tools/install-deps.sh --scene-tools
#   blender -b --factory-startup --python tools/blender/make_second_uv_set.py -- [OUT_DIR]
#
# Writes OUT_DIR (default tests/data/blender/second_uv_set):
#   second_uv_set.gltf + .bin         as exported
#   second_uv_set_baked.gltf + .bin   each plane with only the map its texture reads: what the
#                                     first must look like
#   checker.png                       the texture both use
# A row across the left plane crosses six checker edges (u from 0.25 to 3.25, an edge every 0.5);
# drawn with the first map it would cross one.

import math
import os
import sys

import bpy
from mathutils import Euler, Vector

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from scene_parts import (  # noqa: E402  (this folder, put on the path above)
    build_and_export_twins, checker_image, enable_gltf_exporter, two_planes_camera)

enable_gltf_exporter()

WIDTH, HEIGHT = 256, 128
RED, BLUE = (1.0, 0.0, 0.0, 1.0), (0.0, 0.0, 1.0, 1.0)
# Each plane's second map from its first: (offset u, v), rotation about Z (degrees), (scale u, v).
DETAIL = {
    "left": ((0.25, 0.0), 0.0, (3.0, 2.0)),
    "right": ((0.1, 0.2), 30.0, (2.0, 2.0)),
}
# The map each plane's texture reads.
READS = {"left": "Detail", "right": "UVMap"}


def arguments():
    args = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    return os.path.abspath(args[0] if args else "tests/data/blender/second_uv_set")


def checker(folder):
    # Rows bottom-up: red, blue / blue, red.
    return checker_image(folder, "checker", RED, BLUE)


def material(name, image, uv_map):
    """The checker on base colour and emission, sampled from UV map `uv_map` (a UV Map node for any
    map but the first, as a user picks one)."""
    m = bpy.data.materials.new(name)
    m.use_nodes = True
    nodes, links = m.node_tree.nodes, m.node_tree.links
    bsdf = nodes["Principled BSDF"]
    bsdf.inputs["Roughness"].default_value = 1.0
    bsdf.inputs["Emission Strength"].default_value = 1.0
    tex = nodes.new("ShaderNodeTexImage")
    tex.image = image
    tex.interpolation = "Closest"
    if uv_map != "UVMap":
        uv = nodes.new("ShaderNodeUVMap")
        uv.uv_map = uv_map
        links.new(uv.outputs["UV"], tex.inputs["Vector"])
    links.new(tex.outputs["Color"], bsdf.inputs["Base Color"])
    links.new(tex.outputs["Color"], bsdf.inputs["Emission"])
    return m


def add_detail_map(obj, placement):
    """A second UV map "Detail": the first, scaled, turned and moved (T · R · S)."""
    (ou, ov), rotation, (su, sv) = placement
    turn = Euler((0.0, 0.0, math.radians(rotation))).to_matrix()
    first = obj.data.uv_layers["UVMap"]
    detail = obj.data.uv_layers.new(name="Detail")
    for source, target in zip(first.data, detail.data):
        mapped = turn @ Vector((su * source.uv.x, sv * source.uv.y, 0.0)) + Vector((ou, ov, 0.0))
        target.uv = (mapped.x, mapped.y)
    obj.data.uv_layers.active = first


def build(image):
    for name, x in (("left", -1.1), ("right", 1.1)):
        bpy.ops.mesh.primitive_plane_add(size=2.0, location=(x, 0.0, 0.0))
        plane = bpy.context.object
        plane.name = name
        add_detail_map(plane, DETAIL[name])
        plane.data.materials.append(material("checker_" + name, image, READS[name]))
    two_planes_camera(WIDTH, HEIGHT)


def keep_only_read_maps():
    """Each plane keeps the one map its texture reads, as its first, and loses the UV Map node."""
    for name, read in READS.items():
        obj = bpy.data.objects[name]
        layers = obj.data.uv_layers
        if read != "UVMap":
            for source, target in zip(layers[read].data, layers["UVMap"].data):
                target.uv = source.uv
        layers.remove(layers["Detail"])
        nodes = obj.active_material.node_tree.nodes
        for node in [n for n in nodes if n.bl_idname == "ShaderNodeUVMap"]:
            nodes.remove(node)


def main():
    folder = arguments()
    build_and_export_twins(folder, "second_uv_set", lambda: build(checker(folder)), keep_only_read_maps)


main()
