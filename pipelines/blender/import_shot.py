"""Opens a dewpoint shot in Blender as one scene: the liquid as one object
whose mesh follows the frames, the rigids with their condensed-water
textures driving the roughness as dewpoint-render does, and the scene's
camera, environment and render settings (docs/file-formats.md, "Blender").

  blender -b --python pipelines/blender/import_shot.py -- SHOT [options]   (batch)
  blender --python pipelines/blender/import_shot.py -- SHOT [options]      (opens the UI)
  In Blender's UI: Text Editor > Open this file > Run Script, then
  File > Import > dewpoint shot, and choose SHOT.

SHOT is the folder `dewpoint-simulate -o SHOT` wrote (SHOT/frames), with
`dewpoint-mesh SHOT/frames -o SHOT/meshes` run on it.

options:
  --meshes DIR         liquid meshes, liquid.%04d.ply (default SHOT/meshes)
  --scene FILE         the scene file whose rigid meshes to load (default: the manifest's scene_file)
  --look-dir DIR       where the textures converted for Blender go (default SHOT/blender)
  --oiiotool PATH      OpenImageIO's oiiotool, which converts them (default: found on PATH)
  --no-textures        rigids render dry, nothing is converted
  --save FILE.blend    save the scene; open it with `blender -y` (or allow auto-run scripts) so the liquid follows the frames
  --resolution WxH     replaces render.resolution
  --spp N              replaces render.spp
  --render FRAMES      render these frames (comma-separated indices, `last` for the last) as
  --render-dir DIR     DIR/beauty.%04d.png

Scene files are y-up and Blender is z-up: everything is built in the
scene's coordinates under one empty turned +90 degrees about x, so a
position (x, y, z) shows at Blender's (x, -z, y) and the numbers in the
files stay the numbers in Blender's local coordinates.
"""
import argparse
import json
import math
import os
import shutil
import subprocess
import sys

import bpy
import mathutils
import numpy as np

LIQUID_MESHES_KEY = "dewpoint_liquid_meshes"
FIRST_FRAME_KEY = "dewpoint_first_frame"

# The frame handler lives in a text block registered as a module, so a saved
# .blend brings it back when scripts may run; this session runs the same text.
FRAME_HANDLER_TEXT = "dewpoint_liquid_frames.py"
FRAME_HANDLER_SOURCE = '''"""dewpoint: shows each frame's liquid mesh (pipelines/blender/import_shot.py)."""
import bpy


@bpy.app.handlers.persistent
def dewpoint_show_liquid_frame(scene, depsgraph=None):
    for obj in scene.objects:
        names = obj.get("%s")
        if not names:
            continue
        index = min(max(scene.frame_current - obj["%s"], 0), len(names) - 1)
        mesh = bpy.data.meshes.get(names[index])
        if mesh is not None and obj.data != mesh:
            obj.data = mesh


for handler in list(bpy.app.handlers.frame_change_pre):
    if getattr(handler, "__name__", "") == "dewpoint_show_liquid_frame":
        bpy.app.handlers.frame_change_pre.remove(handler)
bpy.app.handlers.frame_change_pre.append(dewpoint_show_liquid_frame)
''' % (LIQUID_MESHES_KEY, FIRST_FRAME_KEY)


class ShotError(Exception):
    """A shot that cannot be opened; the message names the file and what is wrong."""


# --- reading the shot ---------------------------------------------------------

PLY_TYPES = {"float": "<f4", "float32": "<f4", "double": "<f8", "uint": "<u4", "uint32": "<u4",
             "int": "<i4", "int32": "<i4", "uchar": "u1", "uint8": "u1"}


def read_ply(path):
    """A binary little-endian PLY of triangles (dewpoint's meshes, docs/file-formats.md):
    vertex properties by name as a numpy record array, and the triangles as an (n, 3) array.
    Read here rather than by Blender's importer, which differs between versions, drops the
    normals in 3.x and may remove faces while validating; a vertex count must stay ours."""
    with open(path, "rb") as f:
        data = f.read()
    end = data.find(b"end_header\n")
    if not data.startswith(b"ply\n") or end < 0:
        raise ShotError("%s: not a PLY file (expected 'ply' ... 'end_header')" % path)
    header = data[:end].decode("ascii", "replace").splitlines()
    if "format binary_little_endian 1.0" not in header:
        raise ShotError("%s: expected format binary_little_endian 1.0" % path)
    elements, current = [], None
    for line in header:
        words = line.split()
        if words[:1] == ["element"]:
            current = {"name": words[1], "count": int(words[2]), "properties": []}
            elements.append(current)
        elif words[:1] == ["property"] and current is not None:
            current["properties"].append(words[1:])
    offset = end + len(b"end_header\n")
    vertices, triangles = None, np.zeros((0, 3), dtype=np.int64)
    for element in elements:
        if element["name"] == "vertex":
            dtype = np.dtype([(p[1], PLY_TYPES[p[0]]) for p in element["properties"]])
            vertices = np.frombuffer(data, dtype=dtype, count=element["count"], offset=offset)
            offset += element["count"] * dtype.itemsize
        elif element["name"] == "face":
            if element["properties"] != [["list", "uchar", "int", "vertex_indices"]]:
                raise ShotError("%s: expected faces as 'property list uchar int vertex_indices'" % path)
            faces = np.frombuffer(data, dtype=np.dtype([("n", "u1"), ("i", "<i4", 3)]),
                                  count=element["count"], offset=offset)
            if element["count"] and not np.all(faces["n"] == 3):
                raise ShotError("%s: expected triangles only" % path)
            triangles = faces["i"].astype(np.int64)
            offset += faces.nbytes
        else:
            raise ShotError("%s: unexpected element '%s' before the faces" % (path, element["name"]))
    if vertices is None:
        raise ShotError("%s: no vertex element" % path)
    return vertices, triangles


def mesh_from_ply(path, name):
    """A Blender mesh of a dewpoint PLY: positions, smooth shading with the file's
    normals where it has them, and its `s t` as the UV map where it has them."""
    vertices, triangles = read_ply(path)
    names = vertices.dtype.names
    mesh = bpy.data.meshes.new(name)
    mesh.vertices.add(len(vertices))
    mesh.vertices.foreach_set("co", np.column_stack([vertices["x"], vertices["y"], vertices["z"]]).astype(np.float32).ravel())
    mesh.loops.add(3 * len(triangles))
    mesh.polygons.add(len(triangles))
    mesh.loops.foreach_set("vertex_index", triangles.astype(np.int32).ravel())
    mesh.polygons.foreach_set("loop_start", np.arange(0, 3 * len(triangles), 3, dtype=np.int32))
    mesh.polygons.foreach_set("loop_total", np.full(len(triangles), 3, dtype=np.int32))
    mesh.update()
    if "s" in names and "t" in names:
        uv = mesh.uv_layers.new(name="atlas")
        corners = triangles.ravel()
        uv.data.foreach_set("uv", np.column_stack([vertices["s"][corners], vertices["t"][corners]]).astype(np.float32).ravel())
    mesh.polygons.foreach_set("use_smooth", np.ones(len(triangles), dtype=bool))
    if {"nx", "ny", "nz"} <= set(names) and len(vertices):
        if hasattr(mesh, "use_auto_smooth"):  # Blender before 4.1 needs it for custom normals
            mesh.use_auto_smooth = True
        mesh.normals_split_custom_set_from_vertices(
            np.column_stack([vertices["nx"], vertices["ny"], vertices["nz"]]).astype(np.float32).tolist())
    return mesh


class Shot:
    """What the shot's files say: the manifest (its scene document as run), the
    frames with their liquid meshes and surface textures, and where things are."""

    def __init__(self, folder, meshes_dir=None, scene_file=None):
        self.folder = os.path.abspath(folder)
        self.frames_dir = os.path.join(self.folder, "frames")
        manifest_path = os.path.join(self.frames_dir, "manifest.json")
        if not os.path.isfile(manifest_path):
            raise ShotError("%s: no manifest; expected the folder dewpoint-simulate -o wrote" % manifest_path)
        with open(manifest_path) as f:
            self.manifest = json.load(f)
        if self.manifest.get("format") != "dewpoint-frames":
            raise ShotError("%s: format is %r, expected 'dewpoint-frames'" % (manifest_path, self.manifest.get("format")))
        self.scene = self.manifest["scene"]
        self.name = self.manifest.get("scene_name", "shot")
        self.scene_file = scene_file or self.manifest["scene_file"]
        self.meshes_dir = meshes_dir or os.path.join(self.folder, "meshes")
        self.frames = sorted(self.manifest["frames"], key=lambda frame: frame["index"])
        if not self.frames:
            raise ShotError("%s: lists no frames" % manifest_path)
        self.textured = {r["name"]: os.path.join(self.frames_dir, r["mesh"]) for r in self.manifest.get("rigids", [])}

    def liquid_mesh(self, index):
        return os.path.join(self.meshes_dir, "liquid.%04d.ply" % index)

    def rigid_mesh(self, rigid):
        """The simulator's world-space mesh with its atlas for a textured rigid, else the scene's asset."""
        if rigid["name"] in self.textured:
            return self.textured[rigid["name"]]
        return os.path.normpath(os.path.join(os.path.dirname(self.scene_file), rigid["mesh"]))


# --- liquid -------------------------------------------------------------------

def build_liquid(shot, root, material):
    """One object whose mesh is swapped each frame by the frame handler; each frame's
    mesh is a data block kept in the file, so the .blend needs no PLY to render."""
    names = []
    for frame in shot.frames:
        path = shot.liquid_mesh(frame["index"])
        if not os.path.isfile(path):
            raise ShotError("%s: missing; run dewpoint-mesh %s -o %s (or pass --meshes)" % (path, shot.frames_dir, shot.meshes_dir))
        mesh = mesh_from_ply(path, "liquid.%04d" % frame["index"])
        mesh.materials.append(material)
        mesh.use_fake_user = True
        names.append(mesh.name)
    # Frames between written ones (a --frames range with gaps) show the one before.
    first, last = shot.frames[0]["index"], shot.frames[-1]["index"]
    by_index = {frame["index"]: name for frame, name in zip(shot.frames, names)}
    per_frame, current = [], names[0]
    for index in range(first, last + 1):
        current = by_index.get(index, current)
        per_frame.append(current)
    liquid = bpy.data.objects.new("liquid", bpy.data.meshes[per_frame[0]])
    liquid[LIQUID_MESHES_KEY] = per_frame
    liquid[FIRST_FRAME_KEY] = first
    bpy.context.scene.collection.objects.link(liquid)
    liquid.parent = root
    return liquid


def register_frame_handler():
    text = bpy.data.texts.get(FRAME_HANDLER_TEXT) or bpy.data.texts.new(FRAME_HANDLER_TEXT)
    text.from_string(FRAME_HANDLER_SOURCE)
    text.use_module = True
    exec(compile(FRAME_HANDLER_SOURCE, FRAME_HANDLER_TEXT, "exec"), {"__name__": FRAME_HANDLER_TEXT})


# --- surface textures ---------------------------------------------------------

def convert_surface_texture(oiiotool, source, target):
    """Blender reads only R, G, B, A from an OpenEXR, so each frame's texture becomes
    R = clamp(mass / max_mass), G = wetting, B = 1 inside a chart (max_mass > 0),
    R and G zero outside. Filtered by Blender and divided by the filtered B, they
    are dewpoint-render's rule: texels outside every chart take no part
    (render/surface_texture.cpp). Redone only when the source is newer."""
    if os.path.isfile(target) and os.path.getmtime(target) >= os.path.getmtime(source):
        return
    # oiiotool has no comparison; max_mass x 1e30 clamped to 1 is the chart mask
    # (a texel's capacity is at least a few picograms).
    command = [oiiotool, source, "--ch", "max_mass", "--mulc", "1e30", "--clamp:min=0:max=1", "--label", "mask",
               source, "--ch", "mass", source, "--ch", "max_mass", "--div", "--clamp:min=0:max=1", "mask", "--mul",
               "--label", "fog",
               source, "--ch", "wetting", "--clamp:min=0:max=1", "mask", "--mul", "--label", "wet",
               "fog", "wet", "--chappend", "mask", "--chappend", "--chnames", "R,G,B",
               "-d", "float", "--compression", "zip", "-o", target]
    result = subprocess.run(command, capture_output=True, text=True)
    if result.returncode != 0:
        raise ShotError("%s: oiiotool could not convert it: %s" % (source, result.stderr.strip()))


def surface_look_image(shot, rigid_name, look_dir, oiiotool):
    """The converted textures as one image sequence whose file number is the frame index."""
    os.makedirs(look_dir, exist_ok=True)
    indices = []
    for frame in shot.frames:
        source_name = frame.get("files", {}).get("surfaces", {}).get(rigid_name)
        if source_name is None:
            continue
        convert_surface_texture(oiiotool, os.path.join(shot.frames_dir, source_name),
                                os.path.join(look_dir, "look_%s.%04d.exr" % (rigid_name, frame["index"])))
        indices.append(frame["index"])
    if not indices:
        return None, []
    image = bpy.data.images.load(os.path.join(look_dir, "look_%s.%04d.exr" % (rigid_name, indices[0])))
    image.name = "look_%s" % rigid_name
    image.source = "SEQUENCE"
    image.colorspace_settings.name = "Non-Color"
    return image, indices


# --- materials ----------------------------------------------------------------

def material_settings(d):
    """render.materials.NAME with the defaults of docs/scene-format.md."""
    conductor = d["type"] == "conductor"
    roughness = d.get("roughness", 0.0)
    return {
        "type": d["type"],
        "albedo": d.get("albedo", [1.0, 1.0, 1.0] if conductor else [0.8, 0.8, 0.8]),
        "ior": d.get("ior", 1.33),
        "absorption": d.get("absorption_per_m", [0.0, 0.0, 0.0]),
        "eta": d.get("eta_rgb", [1.657, 0.880, 0.521]),
        "k": d.get("k_rgb", [9.224, 6.270, 4.837]),
        "roughness": roughness,
        "fogged_roughness": d.get("fogged_roughness", roughness),
        "wet_roughness": d.get("wet_roughness", roughness),
        "wet_darkening": d.get("wet_darkening", 0.0),
        "emission": d.get("emission_rgb", [0.0, 0.0, 0.0]),
    }


def conductor_normal_reflectance(eta, k):
    """Fresnel reflectance of a conductor at normal incidence, per channel."""
    return [((n - 1) ** 2 + kk ** 2) / ((n + 1) ** 2 + kk ** 2) for n, kk in zip(eta, k)]


class NodeBuilder:
    """Small helpers over a node tree, so a material reads as its formula."""

    def __init__(self, tree):
        self.tree = tree
        self.nodes = tree.nodes
        self.links = tree.links

    def node(self, kind, **inputs):
        n = self.nodes.new(kind)
        for key, value in inputs.items():
            self.set_input(n, key, value)
        return n

    def set_input(self, node, key, value):
        socket = node.inputs[key] if isinstance(key, int) else node.inputs[key]
        if isinstance(value, bpy.types.NodeSocket):
            self.links.new(value, socket)
        else:
            socket.default_value = value

    def math(self, operation, a, b=0.0):
        n = self.nodes.new("ShaderNodeMath")
        n.operation = operation
        self.set_input(n, 0, a)
        self.set_input(n, 1, b)
        return n.outputs[0]

    def lerp(self, a, b, t):
        """a + (b - a) t for scalars (sockets or numbers)."""
        return self.math("ADD", a, self.math("MULTIPLY", self.math("SUBTRACT", b, a), t))

    def vector(self, operation, a, b):
        n = self.nodes.new("ShaderNodeVectorMath")
        n.operation = operation
        self.set_input(n, 0, a)
        if operation == "SCALE":
            self.set_input(n, "Scale", b)
        else:
            self.set_input(n, 1, b)
        return n.outputs["Vector"]


def surface_state(b, image, first_index, last_index):
    """fog and wetting at the shading point, dewpoint-render's way (see convert_surface_texture)."""
    coords = b.node("ShaderNodeUVMap")
    coords.uv_map = "atlas"
    texture = b.node("ShaderNodeTexImage", Vector=coords.outputs["UV"])
    texture.image = image
    texture.interpolation = "Linear"
    texture.extension = "EXTEND"
    user = texture.image_user
    user.frame_start = first_index
    user.frame_offset = first_index - 1  # file number = frame - start + 1 + offset = the frame index
    user.frame_duration = last_index - first_index + 1  # later frames show the last texture
    user.use_auto_refresh = True
    channels = b.node("ShaderNodeSeparateXYZ", Vector=texture.outputs["Color"])
    in_chart = channels.outputs["Z"]
    fog = b.math("DIVIDE", channels.outputs["X"], in_chart)  # Cycles' division by 0 gives 0
    wetting = b.math("DIVIDE", channels.outputs["Y"], in_chart)
    return fog, wetting


def build_material(name, settings, look=None, wet_paths=True):
    """A Cycles material for render.materials.NAME. With a surface texture
    (look = (image, first index, last index)), the GGX alpha is dewpoint-render's
    (render/material.cpp): alpha = lerp(dry, fogged, fog), then
    lerp(alpha, wet, wetting), and the reflectance is darkened by
    wet_darkening x wetting. Cycles' roughness r means alpha = r^2."""
    m = bpy.data.materials.new(name)
    m.use_nodes = True
    b = NodeBuilder(m.node_tree)
    b.nodes.clear()
    out = b.node("ShaderNodeOutputMaterial")
    s = settings

    alpha, darkening = s["roughness"], 0.0
    if look is not None:
        fog, wetting = surface_state(b, *look)
        alpha = b.lerp(s["roughness"], s["fogged_roughness"], fog)
        if wet_paths:
            alpha = b.lerp(alpha, s["wet_roughness"], wetting)
            darkening = b.math("MULTIPLY", s["wet_darkening"], wetting)
    roughness = b.math("SQRT", alpha) if isinstance(alpha, bpy.types.NodeSocket) else math.sqrt(alpha)
    keep = b.math("SUBTRACT", 1.0, darkening) if isinstance(darkening, bpy.types.NodeSocket) else 1.0

    def tinted(rgb):
        if isinstance(keep, float):
            return (*rgb, 1.0)
        return b.vector("SCALE", tuple(rgb), keep)

    if s["type"] == "diffuse":
        bsdf = b.node("ShaderNodeBsdfDiffuse", Color=tinted(s["albedo"]), Roughness=0.0)
    elif s["type"] == "dielectric":
        bsdf = b.node("ShaderNodeBsdfGlass", Color=tinted([1.0, 1.0, 1.0]), IOR=s["ior"], Roughness=roughness)
        bsdf.distribution = "GGX"
        if max(s["absorption"]) > 0:
            density = max(s["absorption"])
            # Cycles' absorption coefficient is density x (1 - color).
            color = [1 - a / density for a in s["absorption"]]
            volume = b.node("ShaderNodeVolumeAbsorption", Color=(*color, 1.0), Density=density)
            b.links.new(volume.outputs[0], out.inputs["Volume"])
    elif s["type"] == "conductor":
        # Principled metallic from the normal-incidence reflectance of eta + ik, with
        # Blender's own rise towards grazing: Cycles before 4.2 has no complex index.
        f0 = [a * r for a, r in zip(s["albedo"], conductor_normal_reflectance(s["eta"], s["k"]))]
        bsdf = b.node("ShaderNodeBsdfPrincipled", Metallic=1.0, Roughness=roughness)
        b.set_input(bsdf, "Base Color", tinted(f0))
    else:
        raise ShotError("render.materials.%s.type: expected diffuse, dielectric or conductor, found %r" % (name, s["type"]))

    surface = bsdf.outputs[0]
    if max(s["emission"]) > 0:
        # Emission from the front (outside) only, as dewpoint-render's area lights.
        emission = b.node("ShaderNodeEmission", Color=(*s["emission"], 1.0), Strength=1.0)
        lit = b.node("ShaderNodeAddShader")
        b.links.new(surface, lit.inputs[0])
        b.links.new(emission.outputs[0], lit.inputs[1])
        side = b.node("ShaderNodeNewGeometry")
        choose = b.node("ShaderNodeMixShader", Fac=side.outputs["Backfacing"])
        b.links.new(lit.outputs[0], choose.inputs[1])
        b.links.new(surface, choose.inputs[2])
        surface = choose.outputs[0]
    b.links.new(surface, out.inputs["Surface"])
    return m


# --- rigids -------------------------------------------------------------------

def import_asset(path):
    """The scene's own mesh file (world coordinates, y-up) as Blender objects in
    those coordinates, through Blender's importers."""
    if not os.path.isfile(path):
        raise ShotError("%s: rigid mesh not found (pass --scene if the scene moved)" % path)
    before = set(bpy.data.objects)
    extension = os.path.splitext(path)[1].lower()
    if extension == ".ply":
        mesh = mesh_from_ply(path, os.path.basename(path))
        obj = bpy.data.objects.new(mesh.name, mesh)
        bpy.context.scene.collection.objects.link(obj)
        return [obj], False
    if extension == ".obj":
        bpy.ops.wm.obj_import(filepath=path, forward_axis="Y", up_axis="Z")  # no axis change
    elif extension == ".stl":
        if hasattr(bpy.ops.wm, "stl_import"):
            bpy.ops.wm.stl_import(filepath=path, forward_axis="Y", up_axis="Z")
        else:
            bpy.ops.import_mesh.stl(filepath=path, axis_forward="Y", axis_up="Z")
    elif extension in (".gltf", ".glb"):
        bpy.ops.import_scene.gltf(filepath=path)  # glTF is y-up and the importer turns it to z-up itself
        return [o for o in bpy.data.objects if o not in before], True
    else:
        raise ShotError("%s: Blender import of %s meshes is not supported here (OBJ, PLY, STL, glTF)" % (path, extension))
    return [o for o in bpy.data.objects if o not in before], False


def build_rigids(shot, root, materials, look_dir, oiiotool, wet_paths):
    render = shot.scene["render"]
    built = {}
    for rigid in shot.scene["simulation"].get("rigids", []):
        name = rigid["name"]
        path = shot.rigid_mesh(rigid)
        if name in shot.textured:
            mesh = mesh_from_ply(path, name)
            objects, z_up = [bpy.data.objects.new(name, mesh)], False
            bpy.context.scene.collection.objects.link(objects[0])
        else:
            objects, z_up = import_asset(path)
        material_name = render["objects"][name]["material"]
        look = None
        if name in shot.textured and oiiotool is not None:
            image, indices = surface_look_image(shot, name, look_dir, oiiotool)
            if image is not None:
                look = (image, indices[0], indices[-1])
        material = build_material("%s (%s)" % (material_name, name), materials[material_name], look, wet_paths) \
            if look else shared_material(material_name, materials)
        for obj in objects:
            if obj.type == "MESH":
                obj.data.materials.clear()
                obj.data.materials.append(material)
            if obj.parent is None:
                world = obj.matrix_world.copy()
                obj.parent = root
                obj.matrix_parent_inverse = root.matrix_world.inverted() if z_up else mathutils.Matrix.Identity(4)
                if z_up:
                    obj.matrix_world = world
        built[name] = objects
    return built


_shared_materials = {}


def shared_material(name, materials):
    if name not in _shared_materials:
        _shared_materials[name] = build_material(name, materials[name])
    return _shared_materials[name]


# --- camera, world, render settings -------------------------------------------

def look_at_matrix(position, target, up):
    """A Blender camera (looking down -z, up +y) at position, looking at target."""
    p, t, u = (mathutils.Vector(v) for v in (position, target, up))
    forward = (t - p).normalized()
    right = forward.cross(u).normalized()
    true_up = right.cross(forward)
    rotation = mathutils.Matrix((right, true_up, -forward)).transposed()
    return mathutils.Matrix.Translation(p) @ rotation.to_4x4()


def build_camera(shot, root):
    c = shot.scene["render"]["camera"]
    data = bpy.data.cameras.new("camera")
    data.sensor_fit = "VERTICAL"
    data.angle_y = math.radians(c.get("fov_deg", 40))
    data.clip_start = 1e-3
    if c.get("model", "pinhole") == "thin_lens" and c["aperture_radius_m"] > 0:
        data.dof.use_dof = True
        focus = c.get("focus_distance_m", 0) or (mathutils.Vector(c["look_at_m"]) - mathutils.Vector(c["position_m"])).length
        data.dof.focus_distance = focus
        # Blender's aperture radius is lens / (2 f-stop), lens in mm.
        data.dof.aperture_fstop = data.lens / (2000 * c["aperture_radius_m"])
    camera = bpy.data.objects.new("camera", data)
    bpy.context.scene.collection.objects.link(camera)
    camera.parent = root
    camera.matrix_basis = look_at_matrix(c["position_m"], c["look_at_m"], c.get("up", [0, 1, 0]))
    bpy.context.scene.camera = camera
    return camera


def build_world(shot):
    e = shot.scene["render"].get("environment", {})
    kind = e.get("type", "sky")
    world = bpy.data.worlds.new("environment")
    world.use_nodes = True
    b = NodeBuilder(world.node_tree)
    b.nodes.clear()
    background = b.node("ShaderNodeBackground", Strength=e.get("intensity", 1.0))
    b.links.new(background.outputs[0], b.node("ShaderNodeOutputWorld").inputs["Surface"])
    direction = b.node("ShaderNodeTexCoord").outputs["Generated"]  # the ray's direction in a world shader
    if kind == "sky":
        # render/sky_environment.cpp: ground below the horizon, else lerp(horizon, zenith, sin elevation).
        up = b.node("ShaderNodeSeparateXYZ", Vector=direction).outputs["Z"]
        zenith, horizon, ground = (tuple(e.get(k, d)) for k, d in (
            ("zenith_rgb", [0.45, 0.6, 0.9]), ("horizon_rgb", [1.0, 0.97, 0.92]), ("ground_rgb", [0.3, 0.27, 0.24])))
        sky = b.vector("ADD", horizon, b.vector("SCALE", tuple(z - h for z, h in zip(zenith, horizon)), up))
        below = b.math("LESS_THAN", up, 0.0)
        color = b.vector("ADD", b.vector("SCALE", sky, b.math("SUBTRACT", 1.0, below)), b.vector("SCALE", ground, below))
        b.set_input(background, "Color", color)
    elif kind == "constant":
        b.set_input(background, "Color", (*e.get("radiance_rgb", [1, 1, 1]), 1.0))
    elif kind == "map":
        path = os.path.normpath(os.path.join(os.path.dirname(shot.scene_file), e["file"]))
        if not os.path.isfile(path):
            raise ShotError("%s: render.environment.file not found" % path)
        # Our map's centre column looks along the scene's -z, Blender's along +x:
        # a quarter turn, plus the scene's own turn about its up axis.
        mapping = b.node("ShaderNodeMapping", Vector=direction)
        mapping.inputs["Rotation"].default_value = (0, 0, math.radians(e.get("rotation_deg", 0)) - math.pi / 2)
        texture = b.node("ShaderNodeTexEnvironment", Vector=mapping.outputs["Vector"])
        texture.image = bpy.data.images.load(path)
        b.set_input(background, "Color", texture.outputs["Color"])
    else:
        raise ShotError("render.environment.type: expected sky, constant or map, found %r" % kind)
    bpy.context.scene.world = world


def apply_render_settings(shot, resolution=None, spp=None):
    r = shot.scene["render"]
    scene = bpy.context.scene
    scene.render.engine = "CYCLES"
    width, height = resolution or r["resolution"]
    scene.render.resolution_x, scene.render.resolution_y, scene.render.resolution_percentage = width, height, 100
    c = scene.cycles
    c.samples = spp or r.get("spp", 32)
    c.use_adaptive_sampling = False
    c.use_denoising = False
    depth = r.get("max_depth", 12)
    c.max_bounces = c.diffuse_bounces = c.glossy_bounces = c.transmission_bounces = c.transparent_max_bounces = depth
    c.caustics_reflective = c.caustics_refractive = True
    c.sample_clamp_direct = c.sample_clamp_indirect = 0
    c.seed = r.get("seed", 1)
    f = r.get("filter", {})
    kind = f.get("type", "gaussian")
    c.pixel_filter_type = {"box": "BOX", "gaussian": "GAUSSIAN", "tent": "BLACKMAN_HARRIS"}[kind]
    c.filter_width = 2 * f.get("radius_px", {"box": 0.5, "tent": 1.0, "gaussian": 1.5}[kind])
    scene.view_settings.view_transform = "Standard"
    scene.view_settings.exposure = r.get("exposure_stops", 0)
    scene.render.use_lock_interface = True  # the frame handler swaps meshes while Cycles renders
    rate = shot.scene["simulation"].get("frame_rate_hz", 24)
    scene.render.fps, scene.render.fps_base = (int(rate), 1.0) if float(rate).is_integer() else (round(rate * 1000), 1000.0)
    scene.frame_start, scene.frame_end = shot.frames[0]["index"], shot.frames[-1]["index"]


# --- the whole shot -----------------------------------------------------------

def import_shot(folder, meshes_dir=None, scene_file=None, look_dir=None, oiiotool=None, textures=True,
                resolution=None, spp=None):
    """Builds the shot into the current Blender scene; returns its root empty."""
    shot = Shot(folder, meshes_dir, scene_file)
    if textures and shot.textured:
        oiiotool = oiiotool or shutil.which("oiiotool")
        if oiiotool is None:
            raise ShotError("oiiotool not found: install OpenImageIO's tools (Debian: openimageio-tools), "
                            "pass --oiiotool PATH, or --no-textures to render the rigids dry")
    else:
        oiiotool = None
    render = shot.scene["render"]
    materials = {name: material_settings(d) for name, d in render["materials"].items()}
    root = bpy.data.objects.new("dewpoint %s" % shot.name, None)
    bpy.context.scene.collection.objects.link(root)
    root.rotation_euler = (math.pi / 2, 0, 0)  # scene y-up -> Blender z-up
    root["dewpoint_shot"] = shot.folder
    bpy.context.view_layer.update()
    _shared_materials.clear()
    liquid_material = shared_material(render.get("liquid_material", "water"), materials)
    build_liquid(shot, root, liquid_material)
    build_rigids(shot, root, materials, look_dir or os.path.join(shot.folder, "blender"), oiiotool,
                 render.get("wet_paths", True))
    build_camera(shot, root)
    build_world(shot)
    apply_render_settings(shot, resolution, spp)
    register_frame_handler()
    bpy.context.scene.frame_set(shot.frames[0]["index"])
    return root


def render_frames(frames, folder):
    scene = bpy.context.scene
    os.makedirs(folder, exist_ok=True)
    scene.render.image_settings.file_format = "PNG"
    scene.render.image_settings.color_mode = "RGB"
    for frame in frames:
        scene.frame_set(frame)
        scene.render.filepath = os.path.join(folder, "beauty.%04d.png" % frame)
        bpy.ops.render.render(write_still=True)


class DEWPOINT_OT_import_shot(bpy.types.Operator):
    """Import a dewpoint shot (the folder dewpoint-simulate -o wrote)"""
    bl_idname = "dewpoint.import_shot"
    bl_label = "Import dewpoint shot"
    directory: bpy.props.StringProperty(subtype="DIR_PATH")

    def execute(self, context):
        try:
            import_shot(self.directory)
        except ShotError as error:
            self.report({"ERROR"}, str(error))
            return {"CANCELLED"}
        return {"FINISHED"}

    def invoke(self, context, event):
        context.window_manager.fileselect_add(self)
        return {"RUNNING_MODAL"}


def menu_entry(self, context):
    self.layout.operator(DEWPOINT_OT_import_shot.bl_idname, text="dewpoint shot")


def register_import_menu():
    bpy.utils.register_class(DEWPOINT_OT_import_shot)
    bpy.types.TOPBAR_MT_file_import.append(menu_entry)


def parse_arguments(argv):
    p = argparse.ArgumentParser(prog="import_shot.py", description="Open a dewpoint shot in Blender.")
    p.add_argument("shot")
    p.add_argument("--meshes")
    p.add_argument("--scene")
    p.add_argument("--look-dir")
    p.add_argument("--oiiotool")
    p.add_argument("--no-textures", action="store_true")
    p.add_argument("--save")
    p.add_argument("--resolution", type=lambda s: tuple(int(v) for v in s.lower().split("x")))
    p.add_argument("--spp", type=int)
    p.add_argument("--render", default="")
    p.add_argument("--render-dir")
    return p.parse_args(argv)


def main(argv):
    a = parse_arguments(argv)
    bpy.ops.wm.read_factory_settings(use_empty=True)
    import_shot(a.shot, a.meshes, a.scene, a.look_dir, a.oiiotool, not a.no_textures, a.resolution, a.spp)
    scene = bpy.context.scene
    if a.save:
        os.makedirs(os.path.dirname(os.path.abspath(a.save)), exist_ok=True)
        bpy.ops.wm.save_as_mainfile(filepath=os.path.abspath(a.save))
    if a.render:
        frames = [scene.frame_end if f == "last" else int(f) for f in a.render.split(",")]
        render_frames(frames, a.render_dir or os.path.join(os.path.abspath(a.shot), "blender", "images"))


if __name__ == "__main__":
    if "--" in sys.argv:
        try:
            main(sys.argv[sys.argv.index("--") + 1:])
        except ShotError as error:
            print("import_shot.py: %s" % error, file=sys.stderr)
            sys.exit(1)
    else:
        register_import_menu()
