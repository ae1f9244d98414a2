#!/usr/bin/env python3
"""A Glass-sized render benchmark (issue #8; the paper's Glass scene, Fig. 8):
a glass of water on a table under an HDR sky, written as a dewpoint scene
with its frames folder and liquid mesh, so dewpoint-render and Blender
Cycles (cycles_glass.py) render the same meshes, camera and light.

  make_glass_scene.py OUT [--rings N]

OUT/scene.json, OUT/meshes/{floor,glass}.obj, OUT/sky.pfm (convert to
sky.exr with oiiotool), OUT/frames/manifest.json, OUT/liquid/liquid.0000.ply.
The liquid is a closed, smooth, finely tessellated surface (a rounded
cylinder with a rippled top): N^2 triangles, about 313k for N = 560."""
import argparse
import json
import math
import os
import struct

GLASS_R_OUT, GLASS_R_IN, GLASS_H, GLASS_BOTTOM = 0.04, 0.0375, 0.12, 0.006
WATER_R, WATER_BOTTOM, WATER_TOP = 0.0372, 0.0062, 0.085


def write_obj(path, vertices, faces):
    with open(path, "w") as f:
        for v in vertices:
            f.write("v %.7f %.7f %.7f\n" % v)
        for t in faces:
            f.write("f %d %d %d\n" % (t[0] + 1, t[1] + 1, t[2] + 1))


def floor():
    s, y = 2.0, 0.0
    v = [(-s, y, -s), (s, y, -s), (s, y, s), (-s, y, s), (-s, y - 0.05, -s), (s, y - 0.05, -s), (s, y - 0.05, s), (-s, y - 0.05, s)]
    # Counter-clockwise seen from outside.
    f = [(0, 2, 1), (0, 3, 2), (4, 5, 6), (4, 6, 7), (0, 1, 5), (0, 5, 4), (1, 2, 6), (1, 6, 5), (2, 3, 7), (2, 7, 6), (3, 0, 4), (3, 4, 7)]
    return v, f


def revolve(profile, segments):
    """A closed solid of revolution about +y; profile (r, y) runs from the
    axis at the bottom, around the outside, to the axis at the top, so the
    surface winds counter-clockwise seen from outside."""
    vertices, faces = [], []
    rings = []
    for r, y in profile:
        if r == 0:
            rings.append([len(vertices)])
            vertices.append((0.0, y, 0.0))
        else:
            ring = []
            for k in range(segments):
                a = 2 * math.pi * k / segments
                ring.append(len(vertices))
                vertices.append((r * math.cos(a), y, -r * math.sin(a)))
            rings.append(ring)
    for lower, upper in zip(rings, rings[1:]):
        for k in range(segments):
            k1 = (k + 1) % segments
            if len(lower) == 1:
                faces.append((lower[0], upper[k], upper[k1]))
            elif len(upper) == 1:
                faces.append((lower[k], upper[0], lower[k1]))
            else:
                faces.append((lower[k], upper[k], upper[k1]))
                faces.append((lower[k], upper[k1], lower[k1]))
    return vertices, faces


def glass():
    # Outside up, over the rim, inside down to the inner bottom.
    profile = [(0, 0.0), (GLASS_R_OUT, 0.0), (GLASS_R_OUT, GLASS_H), (GLASS_R_IN, GLASS_H), (GLASS_R_IN, GLASS_BOTTOM), (0, GLASS_BOTTOM)]
    return revolve(profile, 256)


def liquid(n):
    """Rounded cylinder with a rippled top as a smooth (theta, phi) grid."""
    def point(t, p):
        # t in [0, 1] from bottom pole to top pole; a superellipse profile.
        a = math.pi * t
        s, c = math.sin(a), -math.cos(a)
        e = 0.2  # squareness
        r = WATER_R * math.copysign(abs(s) ** e, s)
        h = 0.5 * (WATER_TOP - WATER_BOTTOM)
        y = WATER_BOTTOM + h + h * math.copysign(abs(c) ** e, c)
        x, z = r * math.cos(p), -r * math.sin(p)
        if t > 0.5:
            y += 0.0015 * math.sin(60 * x) * math.cos(50 * z) * (t - 0.5) * 2
        return (x, y, z)

    rows, cols = n // 2, n
    vertices = [point(0.0, 0.0)]
    for i in range(1, rows):
        for j in range(cols):
            vertices.append(point(i / rows, 2 * math.pi * j / cols))
    vertices.append(point(1.0, 0.0))
    top = len(vertices) - 1
    idx = lambda i, j: 1 + (i - 1) * cols + (j % cols)
    faces = []
    for j in range(cols):
        faces.append((0, idx(1, j), idx(1, j + 1)))
        faces.append((top, idx(rows - 1, j + 1), idx(rows - 1, j)))
    for i in range(1, rows - 1):
        for j in range(cols):
            faces.append((idx(i, j), idx(i + 1, j), idx(i + 1, j + 1)))
            faces.append((idx(i, j), idx(i + 1, j + 1), idx(i, j + 1)))
    normals = [[0.0, 0.0, 0.0] for _ in vertices]
    for a, b, c in faces:
        va, vb, vc = vertices[a], vertices[b], vertices[c]
        u = [vb[k] - va[k] for k in range(3)]
        w = [vc[k] - va[k] for k in range(3)]
        nrm = (u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0])
        for v in (a, b, c):
            for k in range(3):
                normals[v][k] += nrm[k]
    for nrm in normals:
        l = math.sqrt(sum(x * x for x in nrm)) or 1.0
        for k in range(3):
            nrm[k] /= l
    return vertices, normals, faces


def write_liquid_ply(path, vertices, normals, faces):
    with open(path, "wb") as f:
        f.write(("ply\nformat binary_little_endian 1.0\ncomment Glass benchmark liquid\nelement vertex %d\n"
                 "property float x\nproperty float y\nproperty float z\nproperty float nx\nproperty float ny\nproperty float nz\n"
                 "element face %d\nproperty list uchar int vertex_indices\nend_header\n" % (len(vertices), len(faces))).encode())
        f.write(b"".join(struct.pack("<6f", *v, *n) for v, n in zip(vertices, normals)))
        f.write(b"".join(struct.pack("<B3i", 3, *t) for t in faces))


def write_sky_pfm(path, width=512, height=256):
    """A blue sky brightening to the horizon, a warm sun, a grey ground."""
    sun = (math.radians(35), math.radians(-40))  # elevation, azimuth
    rows = []
    for row in range(height):
        theta = math.pi * (row + 0.5) / height
        line = []
        for col in range(width):
            phi = 2 * math.pi * ((col + 0.5) / width - 0.5)
            d = (math.sin(theta) * math.sin(phi), math.cos(theta), -math.sin(theta) * math.cos(phi))
            if d[1] < 0:
                rgb = (0.25, 0.23, 0.2)
            else:
                k = 1 - d[1]
                rgb = (0.35 + 0.6 * k, 0.5 + 0.45 * k, 0.9 + 0.1 * k)
            s = (math.cos(sun[0]) * math.sin(sun[1]), math.sin(sun[0]), -math.cos(sun[0]) * math.cos(sun[1]))
            if sum(a * b for a, b in zip(d, s)) > math.cos(math.radians(2.5)):
                rgb = (400.0, 360.0, 300.0)
            line.append(rgb)
        rows.append(line)
    with open(path, "wb") as f:
        f.write(b"PF\n%d %d\n-1.0\n" % (width, height))
        for line in reversed(rows):  # PFM rows run bottom to top
            f.write(b"".join(struct.pack("<3f", *rgb) for rgb in line))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("out")
    ap.add_argument("--rings", type=int, default=560)
    args = ap.parse_args()
    for d in ("meshes", "frames", "liquid"):
        os.makedirs(os.path.join(args.out, d), exist_ok=True)
    write_obj(os.path.join(args.out, "meshes/floor.obj"), *floor())
    write_obj(os.path.join(args.out, "meshes/glass.obj"), *glass())
    v, n, faces = liquid(args.rings)
    write_liquid_ply(os.path.join(args.out, "liquid/liquid.0000.ply"), v, n, faces)
    write_sky_pfm(os.path.join(args.out, "sky.pfm"))
    scene = {
        "name": "glass_bench",
        "simulation": {
            "domain": {"min_m": [-0.2, -0.01, -0.2], "max_m": [0.2, 0.3, 0.2]},
            "particle_spacing_m": 0.002,
            "time_step_s": 0.001,
            "duration_s": 0.1,
            "frame_rate_hz": 10,
            "liquid": {"rest_density_kg_m3": 1000},
            "liquid_blocks": [{"min_m": [-0.02, 0.01, -0.02], "max_m": [0.02, 0.05, 0.02]}],
            "rigids": [{"name": "floor", "mesh": "meshes/floor.obj"}, {"name": "glass", "mesh": "meshes/glass.obj"}],
        },
        "render": {
            "resolution": [1280, 720], "spp": 64, "max_depth": 12, "seed": 1,
            "camera": {"position_m": [0.0, 0.13, 0.3], "look_at_m": [0.0, 0.05, 0.0], "fov_deg": 28},
            "filter": {"type": "gaussian"},
            "environment": {"type": "map", "file": "sky.exr"},
            "materials": {
                "water": {"type": "dielectric", "ior": 1.33},
                "glass": {"type": "dielectric", "ior": 1.5},
                "table": {"type": "diffuse", "albedo": [0.6, 0.55, 0.5]},
            },
            "liquid_material": "water",
            "objects": {"floor": {"material": "table"}, "glass": {"material": "glass"}},
        },
    }
    with open(os.path.join(args.out, "scene.json"), "w") as f:
        json.dump(scene, f, indent=1)
    manifest = {"format": "dewpoint-frames", "format_version": 1, "scene_file": os.path.abspath(os.path.join(args.out, "scene.json")),
                "scene_name": "glass_bench", "particle_spacing_m": 0.002, "particle_radius_m": 0.001, "rigid_particles": "none",
                "frames": [{"index": 0, "time_s": 0, "step": 0, "liquid_particles": 0, "files": {"particles": "none"}}]}
    with open(os.path.join(args.out, "frames/manifest.json"), "w") as f:
        json.dump(manifest, f, indent=1)
    print("liquid: %d vertices, %d triangles" % (len(v), len(faces)))


if __name__ == "__main__":
    main()
