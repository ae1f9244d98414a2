"""Renders the Glass benchmark scene of make_glass_scene.py with Blender
Cycles, on the CPU, with the same meshes, camera, environment map, spp and
path length as dewpoint-render:

  blender -b --factory-startup -P cycles_glass.py -- SCENE_DIR OUT.exr SPP WIDTH HEIGHT THREADS [SEED]

Cycles' settings are chosen to match ours: no adaptive sampling, no
denoising, no clamping, caustics on, 12 bounces of every kind. Scene files
are y-up; Blender is z-up, so every position (x, y, z) becomes (x, -z, y)
and the lat-long map is turned about the vertical to keep its orientation
(docs/scene-format.md: the map's centre column looks along -z)."""
import json
import math
import os
import sys
import time

import bpy

arguments = sys.argv[sys.argv.index("--") + 1:]
scene_dir, out_path = arguments[:2]
spp, width, height, threads = (int(a) for a in arguments[2:6])
seed = int(arguments[6]) if len(arguments) > 6 else 1
with open(os.path.join(scene_dir, "scene.json")) as f:
    description = json.load(f)
render = description["render"]


def to_blender(p):
    return (p[0], -p[2], p[1])


bpy.ops.wm.read_factory_settings(use_empty=True)
scene = bpy.context.scene
scene.render.engine = "CYCLES"
c = scene.cycles
c.device = "CPU"
c.samples = spp
c.use_adaptive_sampling = False
c.use_denoising = False
c.max_bounces = c.diffuse_bounces = c.glossy_bounces = c.transmission_bounces = c.transparent_max_bounces = render["max_depth"]
c.volume_bounces = 0
c.sample_clamp_direct = c.sample_clamp_indirect = 0
c.caustics_reflective = c.caustics_refractive = True
c.blur_glossy = 0
c.seed = seed
scene.render.resolution_x, scene.render.resolution_y, scene.render.resolution_percentage = width, height, 100
scene.render.threads_mode = "FIXED"
scene.render.threads = threads
scene.render.image_settings.file_format = "OPEN_EXR"
scene.render.image_settings.color_depth = "32"
scene.view_settings.view_transform = "Standard"
scene.render.filepath = out_path


def material(name, kind, **values):
    m = bpy.data.materials.new(name)
    m.use_nodes = True
    nodes = m.node_tree.nodes
    nodes.clear()
    out = nodes.new("ShaderNodeOutputMaterial")
    if kind == "diffuse":
        bsdf = nodes.new("ShaderNodeBsdfDiffuse")
        bsdf.inputs["Color"].default_value = (*values["albedo"], 1)
    else:
        bsdf = nodes.new("ShaderNodeBsdfGlass")
        bsdf.distribution = "SHARP"
        bsdf.inputs["IOR"].default_value = values["ior"]
        bsdf.inputs["Color"].default_value = (1, 1, 1, 1)
    m.node_tree.links.new(bsdf.outputs[0], out.inputs["Surface"])
    return m


materials = {}
for name, m in render["materials"].items():
    materials[name] = material(name, m["type"], albedo=m.get("albedo", [0.8, 0.8, 0.8]), ior=m.get("ior", 1.33))

start = time.time()
for rigid in description["simulation"]["rigids"]:
    bpy.ops.wm.obj_import(filepath=os.path.join(scene_dir, rigid["mesh"]), forward_axis="NEGATIVE_Z", up_axis="Y")
    obj = bpy.context.selected_objects[0]
    obj.data.materials.append(materials[render["objects"][rigid["name"]]["material"]])
bpy.ops.import_mesh.ply(filepath=os.path.join(scene_dir, "liquid/liquid.0000.ply"))
liquid = bpy.context.selected_objects[0]
liquid.rotation_euler = (math.pi / 2, 0, 0)
bpy.ops.object.shade_smooth()
liquid.data.materials.append(materials[render["liquid_material"]])

cam_data = bpy.data.cameras.new("camera")
cam_data.sensor_fit = "VERTICAL"
cam_data.angle = math.radians(render["camera"]["fov_deg"])
cam = bpy.data.objects.new("camera", cam_data)
scene.collection.objects.link(cam)
cam.location = to_blender(render["camera"]["position_m"])
target = bpy.data.objects.new("target", None)
scene.collection.objects.link(target)
target.location = to_blender(render["camera"]["look_at_m"])
track = cam.constraints.new("TRACK_TO")
track.target = target
track.track_axis = "TRACK_NEGATIVE_Z"
track.up_axis = "UP_Y"
scene.camera = cam

world = bpy.data.worlds.new("sky")
world.use_nodes = True
nodes = world.node_tree.nodes
nodes.clear()
coords = nodes.new("ShaderNodeTexCoord")
mapping = nodes.new("ShaderNodeMapping")
mapping.inputs["Rotation"].default_value = (0, 0, -math.pi / 2)
env = nodes.new("ShaderNodeTexEnvironment")
env.image = bpy.data.images.load(os.path.join(scene_dir, render["environment"]["file"]))
env.interpolation = "Closest"
background = nodes.new("ShaderNodeBackground")
out = nodes.new("ShaderNodeOutputWorld")
links = world.node_tree.links
links.new(coords.outputs["Generated"], mapping.inputs["Vector"])
links.new(mapping.outputs["Vector"], env.inputs["Vector"])
links.new(env.outputs["Color"], background.inputs["Color"])
links.new(background.outputs["Background"], out.inputs["Surface"])
scene.world = world
print("cycles_glass: scene set up in %.1f s" % (time.time() - start))

start = time.time()
bpy.ops.render.render(write_still=True)
seconds = time.time() - start
print("cycles_glass: rendered %dx%d at %d spp on %d threads in %.2f s, %.3f M samples/s" %
      (width, height, spp, threads, seconds, width * height * spp / seconds * 1e-6))
