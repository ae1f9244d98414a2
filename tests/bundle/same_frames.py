"""Two frames folders of one scene hold the same files with the same bytes.

OpenVDB stamps each file with a fresh random UUID (36 bytes after the 21-byte
header start), and the manifest records wall-clock times; those aside, every
byte must agree. Prints the number of files compared; exits 1 naming those
that differ.

    python3 same_frames.py FRAMES_A FRAMES_B
"""
import json
import pathlib
import sys

VDB_UUID = slice(21, 21 + 36)


def without_clock(value):
    if isinstance(value, dict):
        return {k: without_clock(v) for k, v in value.items() if "time" not in k or k == "time_s"}
    if isinstance(value, list):
        return [without_clock(v) for v in value]
    return value


def comparable(path):
    data = bytearray(path.read_bytes())
    if path.suffix == ".vdb":
        data[VDB_UUID] = b"-" * 36
    return bytes(data)


def main(a_dir, b_dir):
    a_dir, b_dir = pathlib.Path(a_dir), pathlib.Path(b_dir)
    names_a = sorted(p.name for p in a_dir.iterdir())
    names_b = sorted(p.name for p in b_dir.iterdir())
    if names_a != names_b:
        print("different files: %s against %s" % (names_a, names_b), file=sys.stderr)
        return 1
    differ = []
    for name in names_a:
        a, b = a_dir / name, b_dir / name
        if name == "manifest.json":
            same = without_clock(json.loads(a.read_text())) == without_clock(json.loads(b.read_text()))
        else:
            same = comparable(a) == comparable(b)
        if not same:
            differ.append(name)
    if differ:
        print("differ: " + " ".join(differ), file=sys.stderr)
        return 1
    print(len(names_a))
    return 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:]))
