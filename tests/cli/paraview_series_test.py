#!/usr/bin/python3
"""dewpoint-simulate --paraview, read back by VTK's own readers (Debian's
python3-vtk9), not by ours: every frame of shot.pvd at its manifest time,
every per-particle attribute equal to the frame's PLY, the air grid holding
the vapor mass the manifest records, and a resumed run's collection keeping
the frames written before it.

usage: paraview_series_test.py DEWPOINT_SIMULATE SOURCE_DIR
"""
import json
import os
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLImageDataReader, vtkXMLPolyDataReader

PLY_TYPES = {"float": "<f4", "uint": "<u4", "int": "<i4", "uchar": "u1"}


def read_ply(path):
    """A binary little-endian PLY's vertices as a numpy record array."""
    with open(path, "rb") as f:
        data = f.read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode("ascii").splitlines()
    count = next(int(l.split()[2]) for l in header if l.startswith("element vertex"))
    fields = [(l.split()[2], PLY_TYPES[l.split()[1]]) for l in header if l.startswith("property")]
    dtype = np.dtype(fields)
    return np.frombuffer(data[end:end + count * dtype.itemsize], dtype=dtype)


def read_xml(reader_class, path):
    reader = reader_class()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def check(condition, what):
    if not condition:
        print("FAIL: " + what)
        sys.exit(1)


def simulate(binary, scene, out, *extra):
    subprocess.run([binary, scene, "-o", out, "--preset", "preview", "--paraview", "--checkpoint-every", "1",
                    "--quiet", *extra], check=True)


def check_series(frames_dir):
    with open(os.path.join(frames_dir, "manifest.json")) as f:
        manifest = json.load(f)
    collection = ET.parse(os.path.join(frames_dir, "shot.pvd")).getroot().find("Collection")
    datasets = {(d.get("part"), d.get("file")): float(d.get("timestep")) for d in collection.findall("DataSet")}
    check(len(datasets) == 2 * len(manifest["frames"]), "shot.pvd lists %d datasets for %d frames (particles and air each)"
          % (len(datasets), len(manifest["frames"])))
    for frame in manifest["frames"]:
        n = frame["index"]
        vtp, vti = "particles.%04d.vtp" % n, "air.%04d.vti" % n
        check(datasets.get(("0", vtp)) == frame["time_s"], "frame %d: particles at the manifest's time" % n)
        check(datasets.get(("1", vti)) == frame["time_s"], "frame %d: air at the manifest's time" % n)

        ply = read_ply(os.path.join(frames_dir, frame["files"]["particles"]))
        poly = read_xml(vtkXMLPolyDataReader, os.path.join(frames_dir, vtp))
        check(poly.GetNumberOfPoints() == len(ply) and poly.GetNumberOfVerts() == len(ply),
              "frame %d: %d points and vertex cells for %d particles" % (n, poly.GetNumberOfPoints(), len(ply)))
        points = vtk_to_numpy(poly.GetPoints().GetData())
        check(np.array_equal(points, np.stack([ply["x"], ply["y"], ply["z"]], axis=1)), "frame %d: positions" % n)
        data = poly.GetPointData()
        velocity = vtk_to_numpy(data.GetArray("velocity"))
        check(np.array_equal(velocity, np.stack([ply["vx"], ply["vy"], ply["vz"]], axis=1)), "frame %d: velocity" % n)
        for name in ("weight", "radius", "temperature", "density", "pressure", "surface_area", "id"):
            check(data.GetArray(name) is not None, "frame %d: no point array %s" % (n, name))
            check(np.array_equal(vtk_to_numpy(data.GetArray(name)), ply[name]), "frame %d: %s differs from the PLY's" % (n, name))

        air = read_xml(vtkXMLImageDataReader, os.path.join(frames_dir, vti))
        vapor = vtk_to_numpy(air.GetCellData().GetArray("vapor_density")).astype(np.float64)
        spacing = air.GetSpacing()
        mass = vapor.sum() * spacing[0] * spacing[1] * spacing[2]
        recorded = frame["air_vapor"]["mass_kg"]
        check(abs(mass - recorded) <= 1e-6 * recorded, "frame %d: air vapor %.9g kg, manifest %.9g kg" % (n, mass, recorded))
        for name in ("temperature", "velocity", "kind"):
            check(air.GetCellData().GetArray(name) is not None, "frame %d: no cell array %s" % (n, name))
    return len(manifest["frames"])


def main(binary, source):
    scene = os.path.join(source, "assets", "scenes", "drop.json")
    with tempfile.TemporaryDirectory(prefix="dewpoint-paraview-") as out:
        simulate(binary, scene, out, "--duration", "0.25")
        check(check_series(os.path.join(out, "frames")) == 3, "three frames in the first run")
        simulate(binary, scene, out, "--duration", "0.375", "--resume")
        check(check_series(os.path.join(out, "frames")) == 4, "four frames after resuming")
    print("paraview series: every frame read back by VTK")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
