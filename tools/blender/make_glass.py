# Makes the glass scene, as a user makes glass in Blender: a Principled BSDF with Transmission 1,
# which the glTF exporter writes as KHR_materials_transmission. On a matte grey floor before a
# matte back wall, lit by a sun from the front-left above (black world):
#   pane       a clear window pane (white, Transmission 1, Roughness 0), 1 cm thick, standing
#              upright between the camera and the orange box
#   tinted     a tinted glass panel (0.3, 0.75, 0.9), Transmission 1, Roughness 0.05), 1 cm thick,
#              standing in the sun's path to the right: its coloured shadow falls on the floor
#   box        an orange matte box (0.8, 0.35, 0.1), seen through the pane
# Each object and its material share the name. IOR is 1.5 (glTF's default; Blender's 1.45 would
# add KHR_materials_ior).
#
# No Cycles render: Cycles refracts the sun through glass only as caustics, which its path tracer
# does not find from a punctual sun (the floor behind glass lies in black shadow), where glTF's
# transmission and Lit draw a thin sheet that lets the sun through.
#
#   tools/install-deps.sh --scene-tools
#   blender -b --factory-startup --python tools/blender/make_glass.py -- [OUT_DIR]
#
# Writes OUT_DIR (default tests/data/blender/glass): glass.gltf + .bin, the scene as exported
# (the sun: KHR_lights_punctual, the exporter's default "Standard" mode, 683 lm/W).

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from scene_parts import (  # noqa: E402  (this folder, put on the path above)
    black_world, box, build_and_export, enable_gltf_exporter, floor_plane, hard_sun, principled, scene_camera)

enable_gltf_exporter()

WIDTH, HEIGHT = 320, 180


def glass(name, color, roughness):
    """A Principled BSDF glass: Transmission 1, IOR 1.5."""
    m = principled(name, color, roughness)
    inputs = m.node_tree.nodes["Principled BSDF"].inputs
    inputs["Transmission"].default_value = 1.0
    inputs["IOR"].default_value = 1.5
    return m


def build():
    floor_plane(10.0, 8.0, principled("floor", (0.5, 0.5, 0.5), roughness=0.9))  # x in [-5, 5], y in [-4, 4]
    box("back_wall", (-5.0, 2.0, 0.0), (5.0, 2.2, 3.0), principled("wall", (0.45, 0.45, 0.45), roughness=0.9))
    box("box", (-1.4, 0.4, 0.0), (-0.4, 1.4, 1.0), principled("box", (0.8, 0.35, 0.1), roughness=0.8))
    box("pane", (-1.9, -0.8, 0.0), (0.1, -0.79, 1.6), glass("pane", (1.0, 1.0, 1.0), 0.0))
    box("tinted", (0.8, -0.2, 0.0), (2.0, -0.19, 1.4), glass("tinted", (0.3, 0.75, 0.9), 0.05))


def add_lights():
    # Sun: 3 W/m² (the exporter writes 3 lux × 683 = 2049), hard shadows, 35° above the horizon,
    # from the left and a little in front (travelling 70° from the camera's line of sight towards
    # +x): the tinted panel's shadow falls on the floor to its right.
    hard_sun(3.0, 35.0, 70.0)


def add_camera():
    scene_camera((0.6, -4.5, 1.5), (0.6, 0.5, 0.4), 60.0, WIDTH, HEIGHT)


def main():
    args = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    folder = os.path.abspath(args[0] if args else "tests/data/blender/glass")
    build_and_export(folder, "glass", build, add_lights, add_camera, black_world)


main()
