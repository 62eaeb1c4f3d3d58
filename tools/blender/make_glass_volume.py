# Makes the glass-volume scene, as a user makes tinted solid glass in Blender: a Principled BSDF
# with Transmission 1 and a Volume Absorption node on the Material Output's Volume, its thickness
# on the exporter's "glTF Material Output" node group, which the glTF exporter writes as
# KHR_materials_volume (attenuationColor the node's colour, attenuationDistance 1 / density,
# thicknessFactor the group's Thickness). Two slabs of the same amber glass (colour (0.8, 0.5,
# 0.25) after 0.2 m) hang 0.8 m over a matte grey floor under a sun 60° high (black world):
#   thin_block   5 cm thick (thickness 0.05)
#   thick_block  20 cm thick (thickness 0.2)
# The camera looks down on both: it sees each slab's top, the floor through it, and beside each
# the floor in the slab's coloured shadow. Each object and its material share the name.
#
# No Cycles render: Cycles refracts the sun through glass only as caustics, which its path tracer
# does not find from a punctual sun (the floor under glass lies in black shadow).
#
#   tools/install-deps.sh --scene-tools
#   blender -b --factory-startup --python tools/blender/make_glass_volume.py -- [OUT_DIR]
#
# Writes OUT_DIR (default tests/data/blender/glass_volume): glass_volume.gltf + .bin (the sun:
# KHR_lights_punctual, 683 lm/W).

import os
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from scene_parts import (  # noqa: E402  (this folder, put on the path above)
    black_world, box, build_and_export, enable_gltf_exporter, floor_plane, hard_sun, principled, scene_camera,
    volume_thickness)

enable_gltf_exporter()

WIDTH, HEIGHT = 160, 90
ATTENUATION_COLOR = (0.8, 0.5, 0.25)
ATTENUATION_DISTANCE = 0.2  # metres


def amber_glass(name, thickness):
    """Clear white glass (Transmission 1, Roughness 0, IOR 1.5) filled with an amber medium."""
    m = principled(name, (1.0, 1.0, 1.0), roughness=0.0)
    nodes, links = m.node_tree.nodes, m.node_tree.links
    bsdf = nodes["Principled BSDF"]
    bsdf.inputs["Transmission"].default_value = 1.0
    bsdf.inputs["IOR"].default_value = 1.5
    absorption = nodes.new("ShaderNodeVolumeAbsorption")
    absorption.inputs["Color"].default_value = (*ATTENUATION_COLOR, 1.0)
    absorption.inputs["Density"].default_value = 1.0 / ATTENUATION_DISTANCE
    links.new(absorption.outputs["Volume"], nodes["Material Output"].inputs["Volume"])
    volume_thickness(m, thickness)
    return m


def build():
    floor_plane(8.0, 8.0, principled("floor", (0.5, 0.5, 0.5), roughness=0.9))
    box("thin_block", (-1.4, -0.5, 0.8), (-0.4, 0.5, 0.85), amber_glass("thin_block", 0.05))
    box("thick_block", (0.4, -0.5, 0.8), (1.4, 0.5, 1.0), amber_glass("thick_block", 0.2))


def add_lights():
    # 3 W/m², hard shadows, 60° above the horizon, travelling towards −y: each slab's shadow falls
    # about half a metre towards the camera, where the camera sees it beside the slab and through it.
    hard_sun(3.0, 60.0, 180.0)


def add_camera():
    scene_camera((0.0, -1.4, 6.0), (0.0, 0.0, 0.5), 45.0, WIDTH, HEIGHT)


def main():
    args = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    folder = os.path.abspath(args[0] if args else "tests/data/blender/glass_volume")
    build_and_export(folder, "glass_volume", build, add_lights, add_camera, black_world)


main()
