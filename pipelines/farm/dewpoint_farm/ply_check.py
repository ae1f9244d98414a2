"""Is a PLY file whole? Its header is read and the size its elements need is
compared with the file's size, so a truncated or half-copied file is found
without reading the data."""
import os

_SCALAR_BYTES = {
    "char": 1, "int8": 1, "uchar": 1, "uint8": 1,
    "short": 2, "int16": 2, "ushort": 2, "uint16": 2,
    "int": 4, "int32": 4, "uint": 4, "uint32": 4, "float": 4, "float32": 4,
    "double": 8, "float64": 8,
}
# Faces of dewpoint's meshes are triangles (docs/file-formats.md), so a list
# property holds 3 entries; a file with other polygons reads as not whole,
# which only costs a redo.
_LIST_ENTRIES = 3


def _header(path):
    with open(path, "rb") as f:
        head = f.read(1 << 16)
    end = head.find(b"end_header\n")
    if not head.startswith(b"ply\n") or end < 0:
        return None, 0
    return head[:end].decode("ascii", "replace").splitlines(), end + len(b"end_header\n")


def ply_element_counts(path):
    """{element: count} of a whole binary little-endian PLY, else None."""
    try:
        lines, data_start = _header(path)
        if lines is None or "format binary_little_endian 1.0" not in lines:
            return None
        counts, sizes, current = {}, {}, None
        for line in lines:
            words = line.split()
            if words[:1] == ["element"] and len(words) == 3:
                current = words[1]
                counts[current] = int(words[2])
                sizes[current] = 0
            elif words[:1] == ["property"] and current is not None:
                if words[1] == "list" and len(words) == 5:
                    sizes[current] += _SCALAR_BYTES[words[2]] + _LIST_ENTRIES * _SCALAR_BYTES[words[3]]
                elif len(words) == 3:
                    sizes[current] += _SCALAR_BYTES[words[1]]
                else:
                    return None
        expected = data_start + sum(counts[e] * sizes[e] for e in counts)
        return counts if os.path.getsize(path) == expected else None
    except (OSError, KeyError, ValueError, IndexError):
        return None
