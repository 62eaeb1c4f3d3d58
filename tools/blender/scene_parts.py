# What the scene makers in this folder build scenes from, as a user builds them in Blender: a
# Principled BSDF material and a box made from the default cube. Imported by make_sun_room.py and
# make_animated_scene.py (which put this folder on sys.path; Blender runs them as scripts).
import bpy


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
