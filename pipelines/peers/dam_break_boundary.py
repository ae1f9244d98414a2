#!/usr/bin/env python3
"""Writes the rigid boundary particles of dewpoint-bench-dam-break (one layer
at the liquid spacing: floor and four walls, no lid; the same loops as
dam_break() in simulate/bench/dam_break_bench.cpp) as a Partio ASCII (.pda)
file, so that the SPlisHSPlasH peer scene can use exactly our boundary
sampling instead of its own (denser) surface sampling.

usage: dam_break_boundary.py [PARTICLES] > dam_break_97k_boundary.pda
"""
import math
import struct
import sys


def f32(x):
    return struct.unpack("f", struct.pack("f", x))[0]


def main():
    particles = int(sys.argv[1]) if len(sys.argv) > 1 else 100000
    a = 1.0
    s = f32(math.cbrt(a * 2 * a * 0.5 * a / particles))
    nz = int(0.5 * a / s)
    gap, lx, ly = 1.2 * s, 4 * a, 2.5 * a
    lz = (nz - 1) * s + 2 * gap
    mx, my, mz = math.ceil(lx / s), math.ceil(ly / s), math.ceil(lz / s)
    dx, dy, dz = lx / mx, ly / my, lz / mz
    p = []
    for k in range(mz + 1):
        for i in range(mx + 1):
            p.append((i * dx, 0.0, k * dz))
    for j in range(1, my + 1):
        for i in range(mx + 1):
            p.append((i * dx, j * dy, 0.0))
            p.append((i * dx, j * dy, lz))
        for k in range(1, mz):
            p.append((0.0, j * dy, k * dz))
            p.append((lx, j * dy, k * dz))
    out = sys.stdout
    out.write("ATTRIBUTES\nposition\nTYPES\nV\nNUMBER_OF_PARTICLES: %d\nBEGIN DATA\n" % len(p))
    for x, y, z in p:
        out.write("%.7g %.7g %.7g\n" % (x, y, z))
    sys.stderr.write("%d boundary particles, spacing %.6g, tank %g x %g x %.6g\n" % (len(p), s, lx, ly, lz))


if __name__ == "__main__":
    main()
