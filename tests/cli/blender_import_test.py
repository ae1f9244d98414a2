#!/usr/bin/python3
"""pipelines/blender/import_shot.py in Debian's Blender, headless, against
readers that are not ours: two short shots (the Fig. 6 drop with its wetted
plate; SCA Logo Tex with its fogged mirror and an OBJ tray) are simulated,
meshed and imported; then

* at every frame the liquid object's mesh has the vertex and triangle count
  of dewpoint-mesh's PLY, and its world-space box is the PLY's box (VTK's
  PLY reader) turned y-up -> z-up;
* the tray from the scene's OBJ sits where the OBJ's own vertex lines say;
* the camera sees the scene's look-at point at the centre of the picture;
* the textures converted for Blender hold the source EXR's
  clamp(mass/max_mass), wetting and chart mask (the source read by oiiotool);
* frame 0 and the last frame render in Cycles, and each picture agrees with
  dewpoint-render's of the same frame: block means of 8 x 8 pixels within
  REL_TOLERANCE of ours (a rigid rendered without its texture fails this).

usage: blender_import_test.py BUILD_DIR SOURCE_DIR   (runs Blender itself)
"""
import json
import os
import subprocess
import sys
import tempfile

import numpy as np

WIDTH, HEIGHT, SPP, BLOCK = 96, 96, 64, 8
# Block means of the two path tracers' pictures: mean |difference| over the
# blocks / mean of ours. Measured 0.3-0.8 % at these settings (Monte Carlo
# noise at 64 spp, Blender's Schlick conductor, Cycles' filter). The fogged
# mirror rendered dry (--no-textures) is 10.8 % off, and with the GGX alpha
# given to Cycles as its roughness (r = alpha instead of r^2 = alpha) 4.1 %.
REL_TOLERANCE = 0.03


def check(condition, what):
    if not condition:
        print("FAIL: " + what)
        sys.exit(1)
    print("ok: " + what)


# --- inside Blender -------------------------------------------------------------

def inside_blender(import_script, shot, report_path, render_dir):
    import importlib.util

    import bpy
    from bpy_extras.object_utils import world_to_camera_view

    spec = importlib.util.spec_from_file_location("import_shot", import_script)
    importer = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(importer)
    bpy.ops.wm.read_factory_settings(use_empty=True)
    importer.import_shot(shot, resolution=(WIDTH, HEIGHT), spp=SPP)
    scene = bpy.context.scene
    liquid = bpy.data.objects["liquid"]
    report = {"frames": {}, "objects": {}}
    for frame in range(scene.frame_start, scene.frame_end + 1):
        scene.frame_set(frame)
        points = np.array([liquid.matrix_world @ v.co for v in liquid.data.vertices]).reshape(-1, 3)
        report["frames"][frame] = {"vertices": len(liquid.data.vertices), "triangles": len(liquid.data.polygons),
                                   "min": points.min(axis=0).tolist() if len(points) else None,
                                   "max": points.max(axis=0).tolist() if len(points) else None}
    for obj in bpy.data.objects:
        if obj.type == "MESH" and obj.name != "liquid":
            points = np.array([obj.matrix_world @ v.co for v in obj.data.vertices])
            report["objects"][obj.name] = {"vertices": len(obj.data.vertices), "min": points.min(axis=0).tolist(),
                                           "max": points.max(axis=0).tolist()}
    camera = importer.Shot(shot).scene["render"]["camera"]
    root = bpy.data.objects["dewpoint %s" % importer.Shot(shot).name]
    target = root.matrix_world @ importer.mathutils.Vector(camera["look_at_m"])
    report["look_at_in_view"] = list(world_to_camera_view(scene, scene.camera, target))[:2]
    importer.render_frames([scene.frame_start, scene.frame_end], render_dir)
    report["rendered"] = [scene.frame_start, scene.frame_end]
    with open(report_path, "w") as f:
        json.dump(report, f)


# --- outside: the shots, the independent readers, the comparisons ---------------

def run(*command):
    subprocess.run([str(c) for c in command], check=True, stdout=subprocess.DEVNULL)


def ply_box(path):
    """Vertex and triangle count and bounding box of a PLY, read by VTK."""
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkIOPLY import vtkPLYReader
    reader = vtkPLYReader()
    reader.SetFileName(path)
    reader.Update()
    data = reader.GetOutput()
    if data.GetNumberOfPoints() == 0:
        return 0, 0, None
    points = vtk_to_numpy(data.GetPoints().GetData())
    return data.GetNumberOfPoints(), data.GetNumberOfPolys(), (points.min(axis=0), points.max(axis=0))


def to_blender(p):
    return np.array([p[0], -p[2], p[1]])


def box_to_blender(low, high):
    corners = np.array([to_blender(c) for c in (low, high)])
    return corners.min(axis=0), corners.max(axis=0)


def oiiotool_pixels(path, channels, scale=1.0):
    """Channels of an OpenEXR as a (height, width, n) array, read by oiiotool.
    Its dump prints 9 decimals, so masses (1e-8 kg) are scaled up first."""
    with tempfile.TemporaryDirectory() as work:
        scaled = os.path.join(work, "scaled.exr")
        subprocess.run(["oiiotool", path, "--ch", ",".join(channels), "--mulc", repr(scale), "-d", "float", "-o", scaled],
                       check=True)
        text = subprocess.run(["oiiotool", "--dumpdata", scaled], check=True, capture_output=True, text=True).stdout
    header, *lines = text.splitlines()
    width, height = (int(v) for v in header.split(":")[1].split(",")[0].split("x"))
    values = [line.split(":")[1].split() for line in lines if line.strip().startswith("Pixel")]
    return np.array(values, dtype=np.float64).reshape(height, width, len(channels))


def png_pixels(path):
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkIOImage import vtkPNGReader
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    width, height, _ = image.GetDimensions()
    return vtk_to_numpy(image.GetPointData().GetScalars()).reshape(height, width, -1)[:, :, :3].astype(np.float64)


def block_difference(ours, theirs):
    a = ours.reshape(HEIGHT // BLOCK, BLOCK, WIDTH // BLOCK, BLOCK, 3).mean(axis=(1, 3))
    b = theirs.reshape(HEIGHT // BLOCK, BLOCK, WIDTH // BLOCK, BLOCK, 3).mean(axis=(1, 3))
    return np.abs(a - b).mean() / a.mean()


def check_shot(build, source, work, scene_name, duration, blender_extra=()):
    scene = os.path.join(source, "assets", "scenes", scene_name + ".json")
    shot = os.path.join(work, scene_name)
    run(os.path.join(build, "simulate", "dewpoint-simulate"), scene, "-o", shot, "--preset", "preview",
        "--duration", duration, "--quiet")
    run(os.path.join(build, "mesh", "dewpoint-mesh"), os.path.join(shot, "frames"), "-o", os.path.join(shot, "meshes"),
        "--quiet")
    report_path, render_dir = os.path.join(shot, "report.json"), os.path.join(shot, "blender_images")
    run("blender", "-b", "--factory-startup", "--python-exit-code", "1", "--python", os.path.abspath(__file__), "--",
        "inside", os.path.join(source, "pipelines", "blender", "import_shot.py"), shot, report_path, render_dir)
    with open(report_path) as f:
        report = json.load(f)
    with open(os.path.join(shot, "frames", "manifest.json")) as f:
        manifest = json.load(f)

    frames = [frame["index"] for frame in manifest["frames"]]
    check(sorted(int(k) for k in report["frames"]) == frames, "%s: Blender's frame range is the manifest's %s" % (scene_name, frames))
    for index in frames:
        got = report["frames"][str(index)]
        vertices, triangles, box = ply_box(os.path.join(shot, "meshes", "liquid.%04d.ply" % index))
        check(got["vertices"] == vertices and got["triangles"] == triangles,
              "%s frame %d: liquid has %d vertices, %d triangles (PLY: %d, %d)"
              % (scene_name, index, got["vertices"], got["triangles"], vertices, triangles))
        if box is not None:
            low, high = box_to_blender(*box)
            error = max(np.abs(np.array(got["min"]) - low).max(), np.abs(np.array(got["max"]) - high).max())
            check(error < 1e-6, "%s frame %d: liquid box at the PLY's, turned z-up (%.1e m off)" % (scene_name, index, error))

    for rigid in manifest["scene"]["simulation"]["rigids"]:
        name = rigid["name"]
        textured = any(r["name"] == name for r in manifest["rigids"])
        if textured:
            vertices, _, (low, high) = ply_box(os.path.join(shot, "frames", "rigid_%s.ply" % name))
        else:
            obj = os.path.normpath(os.path.join(os.path.dirname(scene), rigid["mesh"]))
            with open(obj) as f:
                points = np.array([line.split()[1:4] for line in f if line.startswith("v ")], dtype=np.float64)
            low, high = points.min(axis=0), points.max(axis=0)
        got = report["objects"][name] if name in report["objects"] else next(
            v for k, v in report["objects"].items() if k.startswith(name) or name in k)
        low, high = box_to_blender(low, high)
        error = max(np.abs(np.array(got["min"]) - low).max(), np.abs(np.array(got["max"]) - high).max())
        check(error < 1e-5, "%s: rigid %s (%s) where its file says, turned z-up (%.1e m off)"
              % (scene_name, name, "atlas PLY" if textured else "scene OBJ", error))

    u, v = report["look_at_in_view"]
    check(abs(u - 0.5) < 1e-4 and abs(v - 0.5) < 1e-4, "%s: the look-at point is the picture's centre (%.5f, %.5f)"
          % (scene_name, u, v))

    for rigid in manifest["rigids"]:
        for index in (frames[0], frames[-1]):
            source_exr = os.path.join(shot, "frames", "surface_%s.%04d.exr" % (rigid["name"], index))
            mass, max_mass = np.moveaxis(oiiotool_pixels(source_exr, ["mass", "max_mass"], 1e12), 2, 0)
            wetting = oiiotool_pixels(source_exr, ["wetting"])[:, :, 0]
            inside = max_mass > 0
            expected = np.stack([np.where(inside, np.clip(mass / np.where(inside, max_mass, 1), 0, 1), 0),
                                 np.where(inside, np.clip(wetting, 0, 1), 0), inside.astype(np.float64)], axis=2)
            converted = oiiotool_pixels(os.path.join(shot, "blender", "look_%s.%04d.exr" % (rigid["name"], index)),
                                        ["R", "G", "B"])
            check(np.abs(converted - expected).max() < 1e-6,
                  "%s frame %d: %s's texture for Blender holds fog (max %.3f), wetting (max %.3f) and the chart mask"
                  % (scene_name, index, rigid["name"], expected[:, :, 0].max(), expected[:, :, 1].max()))

    for index in report["rendered"]:
        ours_dir = os.path.join(shot, "images")
        run(os.path.join(build, "render", "dewpoint-render"), scene, "--preset", "preview", "--frames-dir",
            os.path.join(shot, "frames"), "--meshes-dir", os.path.join(shot, "meshes"), "-o", ours_dir,
            "--resolution", "%dx%d" % (WIDTH, HEIGHT), "--spp", SPP, "--frames", "%d-%d" % (index, index), "--aov", "none")
        ours = png_pixels(os.path.join(ours_dir, "beauty.%04d.png" % index))
        theirs = png_pixels(os.path.join(render_dir, "beauty.%04d.png" % index))
        difference = block_difference(ours, theirs)
        check(difference < REL_TOLERANCE, "%s frame %d: Cycles' picture agrees with dewpoint-render's, "
              "block means %.1f %% apart (tolerance %.0f %%)" % (scene_name, index, 100 * difference, 100 * REL_TOLERANCE))


def main():
    if "--" in sys.argv and sys.argv[sys.argv.index("--") + 1] == "inside":
        inside_blender(*sys.argv[sys.argv.index("--") + 2:])
        return
    build, source = sys.argv[1:3]
    with tempfile.TemporaryDirectory() as work:
        check_shot(build, source, work, "drop", "0.25")
        check_shot(build, source, work, "sca_logo_tex", "1.5")


if __name__ == "__main__":
    main()
