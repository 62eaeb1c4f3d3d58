# Makes the normal-map texture-transform test scene: a plane seen from above with a tangent-space
# normal map (4×4 texels, each tilted 35° in its own direction, Closest interpolation) placed by a
# Mapping node that rotates and scales it, as a user tiles a bump texture in Blender. The exporter
# writes the Mapping node as KHR_texture_transform on the normal texture.
#
#   tools/install-deps.sh --scene-tools
#   blender -b --factory-startup --python tools/blender/make_normal_map_transform.py -- [OUT_DIR]
#
# Writes OUT_DIR (default tests/data/blender/normal_map_transform):
#   normal_map_transform.gltf + .bin   the Mapping node as exported (KHR_texture_transform)
#   normal_map_transform_baked.gltf    the same plane with the Mapping applied to its UVs by this
#                                      script and removed: the tangents Lit derives from those UVs
#                                      are the frame the normal map was painted in, so this is
#                                      what the first must look like
#   tilts.png                          the normal map both use
# The Mapping is rotation 60°, scale (2, 1.5), location (0.1, 0.3).

import math
import os
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from scene_parts import (  # noqa: E402  (this folder, put on the path above)
    bake_mapping, build_and_export_twins, enable_gltf_exporter, mapped_image)

enable_gltf_exporter()

WIDTH, HEIGHT = 128, 128
SIDE = 4  # texels per side of the normal map
TILT = math.radians(35.0)
MAPPING = ((0.1, 0.3), 60.0, (2.0, 1.5))  # location (u, v), rotation about Z (degrees), scale (u, v)


def arguments():
    args = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    return os.path.abspath(args[0] if args else "tests/data/blender/normal_map_transform")


def tilts(folder):
    """Texel k tilts the normal by TILT towards azimuth k · 360° / 16 + 10° (tangent space)."""
    image = bpy.data.images.new("tilts", SIDE, SIDE, alpha=False)
    image.colorspace_settings.name = "Non-Color"
    pixels = []
    for k in range(SIDE * SIDE):
        azimuth = math.radians(10.0 + 360.0 * ((k * 7) % (SIDE * SIDE)) / (SIDE * SIDE))
        n = (math.sin(TILT) * math.cos(azimuth), math.sin(TILT) * math.sin(azimuth), math.cos(TILT))
        pixels += [0.5 + 0.5 * n[0], 0.5 + 0.5 * n[1], 0.5 + 0.5 * n[2], 1.0]
    image.pixels = pixels
    image.filepath_raw = os.path.join(folder, "tilts.png")
    image.file_format = "PNG"
    image.save()
    return image


def material(image):
    m = bpy.data.materials.new("tilted")
    m.use_nodes = True
    nodes, links = m.node_tree.nodes, m.node_tree.links
    bsdf = nodes["Principled BSDF"]
    bsdf.inputs["Roughness"].default_value = 1.0
    bsdf.inputs["Base Color"].default_value = (0.8, 0.8, 0.8, 1.0)
    tex = mapped_image(m, image, MAPPING)
    normal_map = nodes.new("ShaderNodeNormalMap")
    links.new(tex.outputs["Color"], normal_map.inputs["Color"])
    links.new(normal_map.outputs["Normal"], bsdf.inputs["Normal"])
    return m


def build(image):
    bpy.ops.mesh.primitive_plane_add(size=2.0, location=(0.0, 0.0, 0.0))
    plane = bpy.context.object
    plane.name = "plane"
    plane.data.materials.append(material(image))
    bpy.ops.object.light_add(type="SUN", location=(0.0, 0.0, 3.0), rotation=(math.radians(40.0), 0.0, math.radians(30.0)))
    bpy.context.object.data.energy = 3.0
    bpy.ops.object.camera_add(location=(0.0, 0.0, 3.0), rotation=(0.0, 0.0, 0.0))  # looks down −Z, +Y up
    cam = bpy.context.object
    cam.name = "camera"
    cam.data.lens_unit = "FOV"
    cam.data.angle = math.radians(36)  # the plane (2 m) fills most of the view
    bpy.context.scene.camera = cam
    bpy.context.scene.render.resolution_x = WIDTH
    bpy.context.scene.render.resolution_y = HEIGHT


def main():
    folder = arguments()
    build_and_export_twins(folder, "normal_map_transform", lambda: build(tilts(folder)),
                           lambda: bake_mapping(bpy.data.objects["plane"], MAPPING), lights=True)


main()
