# Makes tests/data/blender/rig.gltf (+ rig.bin): a scene with what Blender's glTF exporter writes
# that Lit does not draw, for the lossless round-trip test (tests/unit/test_gltf_round_trip.cpp):
# a UV sphere with a shape key whose weight is animated and a colour attribute, an armature with a
# skinned cylinder and an animated bone, a cube mesh shared by two objects (Blender writes its
# accessors once), a camera and a point light.
#
#   blender -b --factory-startup --python tools/blender/make_round_trip_scene.py -- OUT_DIR
#
# Blender 3.4 (Debian's), default export settings.

import os
import sys

import bpy

out_dir = sys.argv[sys.argv.index("--") + 1] if "--" in sys.argv else "."
bpy.ops.wm.read_factory_settings(use_empty=True)

bpy.ops.mesh.primitive_uv_sphere_add(segments=16, ring_count=8)
blob = bpy.context.object
blob.name = "Blob"
blob.shape_key_add(name="Basis")
puff = blob.shape_key_add(name="Puff")
for v in puff.data:
    v.co *= 1.3
puff.value = 0.0
puff.keyframe_insert("value", frame=1)
puff.value = 1.0
puff.keyframe_insert("value", frame=20)
blob.data.color_attributes.new(name="Col", type='BYTE_COLOR', domain='CORNER')

bpy.ops.object.armature_add(location=(3, 0, 0))
armature = bpy.context.object
bpy.ops.mesh.primitive_cylinder_add(location=(3, 0, 1), depth=2)
cylinder = bpy.context.object
cylinder.select_set(True)
armature.select_set(True)
bpy.context.view_layer.objects.active = armature
bpy.ops.object.parent_set(type='ARMATURE_AUTO')
bone = armature.pose.bones[0]
bone.rotation_mode = 'XYZ'
bone.rotation_euler = (0, 0, 0)
bone.keyframe_insert("rotation_euler", frame=1)
bone.rotation_euler = (0.5, 0, 0)
bone.keyframe_insert("rotation_euler", frame=20)

bpy.ops.mesh.primitive_cube_add(location=(-3, 0, 0))
bpy.ops.object.duplicate(linked=True)
bpy.context.object.location = (-3, 3, 0)
bpy.ops.object.camera_add(location=(0, -10, 3), rotation=(1.3, 0, 0))
bpy.ops.object.light_add(type='POINT', location=(0, 0, 5))

bpy.ops.export_scene.gltf(filepath=os.path.join(out_dir, "rig.gltf"), export_format='GLTF_SEPARATE')
