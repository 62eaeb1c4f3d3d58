# Makes the material layers scene, as a user makes one in Blender to show off the layers of the
# Principled BSDF that the glTF exporter writes as extensions: seven spheres in a row on a matte
# grey floor before a matte back wall, lit by a sun from the front-left above and a point light
# from the front-right, black world. From left to right (each sphere and its material share the
# name):
#   plain            red dielectric (0.6, 0.1, 0.1), roughness 0.6, no extension: the control
#   clearcoat        the same base under Clearcoat 1.0, Clearcoat Roughness 0.05
#   clearcoat_rough  the same base under Clearcoat 0.6, Clearcoat Roughness 0.35
#   specular         white dielectric (0.8, 0.8, 0.8), roughness 0.3, Specular 1.0
#                    (KHR_materials_specular: specularColorFactor 2, so F0 = 0.08)
#   ior              the same white, Specular 0.5, Specular Tint 0.5, IOR 2.2
#                    (KHR_materials_specular with a colour and KHR_materials_ior 2.2)
#   coated_metal     gold (1.0, 0.77, 0.34), metallic 1, roughness 0.4, under Clearcoat 1.0,
#                    Clearcoat Roughness 0.1
#   sheen            dark blue dielectric cloth (0.05, 0.08, 0.25), roughness 0.9, with a
#                    Velvet BSDF (Color (0.8, 0.8, 0.8), Sigma 0.5) added to the Principled BSDF
#                    by an Add Shader (KHR_materials_sheen: sheenColorFactor 0.8,
#                    sheenRoughnessFactor 0.5)
# The other spheres have IOR 1.5 (glTF's default; Blender's is 1.45), so that only `ior` gets
# KHR_materials_ior: the exporter writes it with any KHR_materials_specular when IOR is not 1.5.
# Blender 3.x's Principled BSDF takes its dielectric F0 from Specular (0.08 × Specular), not from
# IOR, and the exporter keeps that F0: `ior`'s specularColorFactor 0.284 times F0(2.2) = 0.1406
# gives 0.04 again, as `plain`'s.
# Blender 3.4's exporter reads KHR_materials_sheen from a Velvet BSDF that reaches the Material
# Output (Color: sheenColorFactor, Sigma: sheenRoughnessFactor), as its importer builds the
# extension: Velvet and Principled into an Add Shader; a "glTF Material Output" group does not
# carry sheen.
#
#   tools/install-deps.sh --scene-tools
#   blender -b --factory-startup --python tools/blender/make_material_layers.py -- [OUT_DIR] [--render SAMPLES]
#
# Writes OUT_DIR (default tests/data/blender/material_layers):
#   material_layers.gltf + .bin   the scene as exported (lights: KHR_lights_punctual, the
#                                 exporter's default "Standard" mode, 683 lm/W)
#   material_layers_cycles.png    with --render: a Cycles render (CPU, 320 × 180, SAMPLES samples,
#                                 no denoising, Standard view transform, exposure 0) to compare
#                                 with by eye. Cycles' Principled BSDF (Blender 3.x) weights its
#                                 clear coat by 0.25 × Clearcoat and does not dim the base under it,
#                                 where glTF's coat has full weight and dims the base by its Fresnel
#                                 term: the coats look weaker there than in a glTF viewer. The
#                                 Add Shader sums the Velvet and the base, where glTF's sheen
#                                 dims the base by the sheen's albedo: `sheen` looks brighter.

import os
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from scene_parts import (  # noqa: E402  (this folder, put on the path above)
    black_world, box, build_and_export, cycles_on_cpu, enable_gltf_exporter, floor_plane, hard_sun, principled,
    scene_camera)

enable_gltf_exporter()

WIDTH, HEIGHT = 320, 180
RADIUS = 0.35   # sphere radius, m
SPACING = 0.8   # between sphere centres along x, m
RED = (0.6, 0.1, 0.1)
WHITE = (0.8, 0.8, 0.8)
GOLD = (1.0, 0.77, 0.34)
CLOTH = (0.05, 0.08, 0.25)


def arguments():
    """OUT_DIR and the number of Cycles samples (0: no render)."""
    args = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    samples = 0
    if "--render" in args:  # not "--cycles": Cycles reads the arguments after "--" too and takes it for its own
        at = args.index("--render")
        samples = int(args[at + 1])
        del args[at:at + 2]
    return os.path.abspath(args[0] if args else "tests/data/blender/material_layers"), samples


def layered(name, color, roughness, metallic=0.0, clearcoat=0.0, clearcoat_roughness=0.03, specular=0.5,
            specular_tint=0.0, ior=1.5):
    """principled() with the Principled BSDF's layer inputs set (Blender's defaults but for IOR)."""
    m = principled(name, color, roughness, metallic)
    inputs = m.node_tree.nodes["Principled BSDF"].inputs
    inputs["Clearcoat"].default_value = clearcoat
    inputs["Clearcoat Roughness"].default_value = clearcoat_roughness
    inputs["Specular"].default_value = specular
    inputs["Specular Tint"].default_value = specular_tint
    inputs["IOR"].default_value = ior
    return m


def sheened(name, color, roughness, sheen_color, sheen_roughness):
    """layered() with a Velvet BSDF added to the Principled BSDF (Add Shader into the Material
    Output), as the glTF importer builds KHR_materials_sheen and the exporter reads it back."""
    m = layered(name, color, roughness)
    nodes, links = m.node_tree.nodes, m.node_tree.links
    velvet = nodes.new("ShaderNodeBsdfVelvet")
    velvet.inputs["Color"].default_value = (*sheen_color, 1.0)
    velvet.inputs["Sigma"].default_value = sheen_roughness
    add = nodes.new("ShaderNodeAddShader")
    links.new(velvet.outputs["BSDF"], add.inputs[0])
    links.new(nodes["Principled BSDF"].outputs["BSDF"], add.inputs[1])
    links.new(add.outputs["Shader"], nodes["Material Output"].inputs["Surface"])
    return m


def spheres():
    """The row of spheres along x, left to right as the camera sees them, resting on the floor."""
    row = [
        layered("plain", RED, 0.6),
        layered("clearcoat", RED, 0.6, clearcoat=1.0, clearcoat_roughness=0.05),
        layered("clearcoat_rough", RED, 0.6, clearcoat=0.6, clearcoat_roughness=0.35),
        layered("specular", WHITE, 0.3, specular=1.0),
        layered("ior", WHITE, 0.3, specular=0.5, specular_tint=0.5, ior=2.2),
        layered("coated_metal", GOLD, 0.4, metallic=1.0, clearcoat=1.0, clearcoat_roughness=0.1),
        sheened("sheen", CLOTH, 0.9, sheen_color=WHITE, sheen_roughness=0.5),
    ]
    for i, m in enumerate(row):
        x = (i - (len(row) - 1) / 2) * SPACING
        bpy.ops.mesh.primitive_uv_sphere_add(radius=RADIUS, location=(x, 0.0, RADIUS), segments=48, ring_count=24)
        sphere = bpy.context.object
        sphere.name = m.name
        sphere.data.name = m.name
        sphere.data.materials.append(m)
        bpy.ops.object.shade_smooth()


def build():
    floor_plane(12.0, 8.0, principled("floor", (0.5, 0.5, 0.5), roughness=0.9))  # x in [-6, 6], y in [-4, 4]
    box("back_wall", (-6.0, 1.5, 0.0), (6.0, 1.7, 4.0), principled("wall", (0.45, 0.45, 0.45), roughness=0.9))
    spheres()


def add_lights():
    # Sun: 3 W/m² (the exporter writes 3 lux × 683 = 2049), hard shadows, 45° above the horizon,
    # from the front-left (30° to the left of the camera's line of sight, towards +x and +y).
    hard_sun(3.0, 45.0, 30.0)
    # Point light: 60 W (60 / 4π W/sr, the exporter writes × 683 cd), front-right above the row.
    bpy.ops.object.light_add(type="POINT", location=(2.0, -2.0, 2.2))
    point = bpy.context.object
    point.name = point.data.name = "point"
    point.data.energy = 60.0
    point.data.shadow_soft_size = 0.0  # a point, as KHR_lights_punctual's


def add_camera():
    scene_camera((0.0, -6.0, 1.6), (0.0, 0.0, 0.45), 55.0, WIDTH, HEIGHT)  # the row (5.5 m) fills most of the width


def render(path, samples):
    scene = cycles_on_cpu(samples)
    scene.view_settings.exposure = 0.0
    scene.view_settings.gamma = 1.0
    scene.render.image_settings.file_format = "PNG"
    scene.render.image_settings.color_mode = "RGB"
    scene.render.filepath = path
    bpy.ops.render.render(write_still=True)


def main():
    folder, samples = arguments()
    build_and_export(folder, "material_layers", build, add_lights, add_camera, black_world)
    if samples > 0:
        render(os.path.join(folder, "material_layers_cycles.png"), samples)


main()
