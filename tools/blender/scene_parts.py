# What the scene makers in this folder build scenes from, as a user builds them in Blender: a
# Principled BSDF material, a box made from the default cube, a black world, a Mapping node placing an image and
# the same Mapping baked into a mesh's UVs; and the fixed Cycles settings the comparison renders use. Imported by the make_*.py scripts here (which put this
# folder on sys.path; Blender runs them as scripts).
import math
import os
import sys

import bpy
from mathutils import Euler, Vector


def enable_gltf_exporter():
    """Blender 3.4's glTF exporter still uses numpy's removed `numpy.bool` alias: set it, or exit
    with what to install when Blender's Python has no numpy."""
    try:
        import numpy

        numpy.bool = bool
    except ImportError:
        script = os.path.basename(sys.argv[sys.argv.index("--python") + 1]) if "--python" in sys.argv else "scene maker"
        sys.exit(script + ": Blender's glTF exporter needs numpy: run tools/install-deps.sh --scene-tools")


def principled(name, color, roughness=0.8, metallic=0.0):
    """A Principled BSDF material of base colour `color` (linear RGB), F0 0.04 as glTF's dielectric."""
    m = bpy.data.materials.new(name)
    m.use_nodes = True
    bsdf = m.node_tree.nodes["Principled BSDF"]
    bsdf.inputs["Base Color"].default_value = (*color, 1.0)
    bsdf.inputs["Roughness"].default_value = roughness
    bsdf.inputs["Metallic"].default_value = metallic
    bsdf.inputs["Specular"].default_value = 0.5  # F0 = 0.04, glTF's dielectric
    return m


def volume_thickness(material, thickness):
    """Gives `material` a volume `thickness` metres thick the way Blender's glTF exporter reads it:
    the Thickness input of a "glTF Material Output" node group (the add-on's own menu makes the
    same group), written as KHR_materials_volume's thicknessFactor."""
    group = bpy.data.node_groups.get("glTF Material Output")
    if group is None:
        group = bpy.data.node_groups.new("glTF Material Output", "ShaderNodeTree")
        group.inputs.new("NodeSocketFloat", "Thickness")
    node = material.node_tree.nodes.new("ShaderNodeGroup")
    node.node_tree = group
    node.inputs["Thickness"].default_value = thickness


def box(name, lo, hi, mat):
    """A box from corner `lo` to corner `hi` (Blender axes, metres), scale applied, material `mat`."""
    centre = [(a + b) / 2 for a, b in zip(lo, hi)]
    size = [b - a for a, b in zip(lo, hi)]
    bpy.ops.mesh.primitive_cube_add(size=1.0, location=centre)
    obj = bpy.context.object
    obj.scale = size
    bpy.ops.object.transform_apply(location=False, rotation=False, scale=True)
    obj.name = name
    obj.data.materials.append(mat)
    return obj


def mapped_image(material, image, mapping):
    """An Image Texture node (Closest) of `image` sampled through a Mapping node (Point type) from
    the UVs, as a user tiles a texture: mapping = ((location u, v), rotation about Z in degrees,
    (scale u, v)). Returns the image node; the exporter writes the Mapping as KHR_texture_transform."""
    (lu, lv), rotation, (su, sv) = mapping
    nodes, links = material.node_tree.nodes, material.node_tree.links
    tex = nodes.new("ShaderNodeTexImage")
    tex.image = image
    tex.interpolation = "Closest"
    coords = nodes.new("ShaderNodeTexCoord")
    node = nodes.new("ShaderNodeMapping")
    node.vector_type = "POINT"
    node.inputs["Location"].default_value = (lu, lv, 0.0)
    node.inputs["Rotation"].default_value = (0.0, 0.0, math.radians(rotation))
    node.inputs["Scale"].default_value = (su, sv, 1.0)
    links.new(coords.outputs["UV"], node.inputs["Vector"])
    links.new(node.outputs["Vector"], tex.inputs["Vector"])
    return tex


def bake_mapping(obj, mapping):
    """Applies `mapping` (as mapped_image takes it; Blender's Point mapping: T · R · S) to the
    object's active UVs and removes its material's Mapping and Texture Coordinate nodes."""
    (lu, lv), rotation, (su, sv) = mapping
    turn = Euler((0.0, 0.0, math.radians(rotation))).to_matrix()
    for loop_uv in obj.data.uv_layers.active.data:
        mapped = turn @ Vector((su * loop_uv.uv.x, sv * loop_uv.uv.y, 0.0)) + Vector((lu, lv, 0.0))
        loop_uv.uv = (mapped.x, mapped.y)
    nodes = obj.active_material.node_tree.nodes
    nodes.remove(nodes["Mapping"])
    nodes.remove(nodes["Texture Coordinate"])


def floor_plane(size_x, size_y, mat):
    """A floor plane "floor" at z = 0 centred on the origin, size_x × size_y metres, scale applied."""
    bpy.ops.mesh.primitive_plane_add(size=1.0, location=(0.0, 0.0, 0.0))
    floor = bpy.context.object
    floor.name = floor.data.name = "floor"
    floor.scale = (size_x, size_y, 1.0)
    bpy.ops.object.transform_apply(location=False, rotation=False, scale=True)
    floor.data.materials.append(mat)
    return floor


def hard_sun(energy, elevation, azimuth):
    """A sun lamp "sun" of `energy` W/m² with hard shadows (angle 0), `elevation` degrees above the
    horizon, travelling `azimuth` degrees from +y towards +x."""
    bpy.ops.object.light_add(type="SUN", location=(-3.0, -4.0, 5.0))
    sun = bpy.context.object
    sun.name = sun.data.name = "sun"
    sun.data.energy = energy
    sun.data.angle = 0.0
    elevation, azimuth = math.radians(elevation), math.radians(azimuth)
    direction = Vector((math.sin(azimuth) * math.cos(elevation), math.cos(azimuth) * math.cos(elevation),
                        -math.sin(elevation)))
    sun.rotation_euler = direction.to_track_quat("-Z", "Y").to_euler()
    return sun


def scene_camera(location, target, horizontal_fov, width, height):
    """The scene's camera "camera" at `location` looking at `target`, `horizontal_fov` degrees wide,
    rendering width × height pixels."""
    bpy.ops.object.camera_add(location=location)
    cam = bpy.context.object
    cam.name = "camera"
    cam.data.lens_unit = "FOV"
    cam.data.sensor_fit = "HORIZONTAL"
    cam.data.angle = math.radians(horizontal_fov)
    direction = Vector(target) - cam.location
    cam.rotation_euler = direction.to_track_quat("-Z", "Y").to_euler()
    scene = bpy.context.scene
    scene.camera = cam
    scene.render.resolution_x = width
    scene.render.resolution_y = height
    scene.render.resolution_percentage = 100
    return cam


def build_and_export(folder, name, *steps):
    """Runs `steps` (functions building the scene) on an empty factory scene, then exports it with
    Blender's glTF exporter as folder/name.gltf + .bin, cameras and lights included."""
    os.makedirs(folder, exist_ok=True)
    bpy.ops.wm.read_factory_settings(use_empty=True)
    for step in steps:
        step()
    bpy.ops.export_scene.gltf(filepath=os.path.join(folder, name + ".gltf"), export_format="GLTF_SEPARATE",
                              export_cameras=True, export_lights=True, export_apply=True)


def black_world():
    """A black world: the scene is lit by its lamps alone."""
    world = bpy.data.worlds.new("black")
    bpy.context.scene.world = world
    world.use_nodes = True
    background = world.node_tree.nodes["Background"]
    background.inputs["Color"].default_value = (0.0, 0.0, 0.0, 1.0)
    background.inputs["Strength"].default_value = 0.0


def cycles_on_cpu(samples):
    """Cycles on the CPU with `samples` samples a pixel, fixed: no adaptive sampling, no
    denoising, seed 1, the Standard view transform without a look (the linear light as it is)."""
    scene = bpy.context.scene
    scene.render.engine = "CYCLES"
    scene.cycles.device = "CPU"
    scene.cycles.samples = samples
    scene.cycles.use_adaptive_sampling = False
    scene.cycles.use_denoising = False
    scene.cycles.seed = 1
    scene.view_settings.view_transform = "Standard"
    scene.view_settings.look = "None"
    return scene


def checker_image(folder, name, first, second, is_data=False):
    """A 2×2 checker image `name` (rows bottom-up: first, second / second, first; RGBA colours),
    saved as folder/name.png; `is_data` makes it Non-Color data (a factor, not a colour)."""
    image = bpy.data.images.new(name, 2, 2, alpha=False, is_data=is_data)
    image.pixels = [*first, *second, *second, *first]
    image.filepath_raw = os.path.join(folder, name + ".png")
    image.file_format = "PNG"
    image.save()
    return image


def two_planes_camera(width, height):
    """The camera over the two 2 m planes at x = ±1.1 m: 4 m up, looking down −Z with +Y up, wide
    enough for both (x from −2.1 to 2.1 m) with a margin."""
    bpy.ops.object.camera_add(location=(0.0, 0.0, 4.0), rotation=(0.0, 0.0, 0.0))
    cam = bpy.context.object
    cam.name = "camera"
    cam.data.lens_unit = "FOV"
    cam.data.sensor_fit = "HORIZONTAL"
    cam.data.angle = math.radians(62)
    bpy.context.scene.camera = cam
    bpy.context.scene.render.resolution_x = width
    bpy.context.scene.render.resolution_y = height


def export_separate(path, lights=False):
    """Blender's glTF exporter: path (.gltf + .bin + images), cameras (and with `lights` the lamps)
    included, modifiers applied."""
    bpy.ops.export_scene.gltf(filepath=path, export_format="GLTF_SEPARATE", export_cameras=True,
                              export_lights=lights, export_apply=True)


def build_and_export_twins(folder, name, build, make_twin, lights=False):
    """Runs `build` on an empty factory scene and exports it as folder/name.gltf, then runs
    `make_twin` (what the first must look like, made another way: a mapping baked into the UVs)
    and exports that as folder/name_baked.gltf."""
    os.makedirs(folder, exist_ok=True)
    bpy.ops.wm.read_factory_settings(use_empty=True)
    build()
    export_separate(os.path.join(folder, name + ".gltf"), lights)
    make_twin()
    export_separate(os.path.join(folder, name + "_baked.gltf"), lights)
