# Makes the glass-refraction scene, as a user makes a solid block of clear glass in Blender: a
# Principled BSDF with Transmission 1 and IOR 1.5, its thickness on the exporter's "glTF Material
# Output" node group (KHR_materials_volume's thicknessFactor; no Volume Absorption: clear glass),
# so that glTF viewers bend the view through it. On a matte grey floor (black world):
#   block   a block of clear glass 1.2 m wide, 1.2 m tall and 0.3 m thick (thickness 0.3), standing
#           upright between the camera and the wall
#   wall    a wall 0.9 m behind it, painted with a black/white checker of 0.2 m cells (an Image
#           Texture through a Mapping node: KHR_texture_transform)
# The camera looks at the block's face 34° off its normal, so what it sees of the checker through
# the block is shifted by the bend (about 8 cm across the block). A sun 50° high behind the camera
# lights the wall. Each object and its material share the name.
#
# No Cycles render: Cycles refracts the sun through the glass only as caustics, which its path
# tracer does not find from a punctual sun (the wall behind the block lies in black shadow).
#
#   tools/install-deps.sh --scene-tools
#   blender -b --factory-startup --python tools/blender/make_glass_refraction.py -- [OUT_DIR]
#
# Writes OUT_DIR (default tests/data/blender/glass_refraction): glass_refraction.gltf + .bin and
# the checker image (the sun: KHR_lights_punctual, 683 lm/W).

import math
import os
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from scene_parts import (  # noqa: E402  (this folder, put on the path above)
    black_world, box, build_and_export, checker_image, enable_gltf_exporter, floor_plane, hard_sun,
    mapped_image, principled, scene_camera, volume_thickness)

enable_gltf_exporter()

WIDTH, HEIGHT = 320, 180
BLACK, WHITE = (0.02, 0.02, 0.02, 1.0), (0.8, 0.8, 0.8, 1.0)
WALL_WIDTH, WALL_HEIGHT, CELL = 6.0, 2.5, 0.2


def clear_glass(name, thickness):
    """Clear white glass: Transmission 1, Roughness 0, IOR 1.5, a volume `thickness` metres thick."""
    m = principled(name, (1.0, 1.0, 1.0), roughness=0.0)
    nodes = m.node_tree.nodes
    bsdf = nodes["Principled BSDF"]
    bsdf.inputs["Transmission"].default_value = 1.0
    bsdf.inputs["IOR"].default_value = 1.5
    volume_thickness(m, thickness)
    return m


def checker_wall(folder):
    """The wall: an upright plane whose base colour is a 2×2 checker tiled to CELL-sized cells."""
    image = checker_image(folder, "wall_checker", WHITE, BLACK)
    m = principled("wall", (1.0, 1.0, 1.0), roughness=0.9)
    tex = mapped_image(m, image, ((0.0, 0.0), 0.0, (WALL_WIDTH / (2 * CELL), WALL_HEIGHT / (2 * CELL))))
    m.node_tree.links.new(tex.outputs["Color"], m.node_tree.nodes["Principled BSDF"].inputs["Base Color"])
    bpy.ops.mesh.primitive_plane_add(size=1.0, location=(0.0, 0.9, WALL_HEIGHT / 2))
    wall = bpy.context.object
    wall.name = wall.data.name = "wall"
    wall.scale = (WALL_WIDTH, WALL_HEIGHT, 1.0)
    wall.rotation_euler = (math.radians(90.0), 0.0, 0.0)  # facing −y, towards the camera
    bpy.ops.object.transform_apply(location=False, rotation=True, scale=True)
    wall.data.materials.append(m)


def build(folder):
    floor_plane(8.0, 8.0, principled("floor", (0.5, 0.5, 0.5), roughness=0.9))
    checker_wall(folder)
    box("block", (-0.6, -0.15, 0.0), (0.6, 0.15, 1.2), clear_glass("block", 0.3))


def add_lights():
    # 3 W/m², hard shadows, 50° above the horizon, travelling towards +y and a little +x.
    hard_sun(3.0, 50.0, 20.0)


def add_camera():
    scene_camera((-2.2, -3.2, 0.8), (0.0, 0.3, 0.6), 50.0, WIDTH, HEIGHT)


def main():
    args = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    folder = os.path.abspath(args[0] if args else "tests/data/blender/glass_refraction")
    build_and_export(folder, "glass_refraction", lambda: build(folder), add_lights, add_camera, black_world)


main()
