#!/usr/bin/python3
"""Writes assets/wall_corner.gltf: a static scene piece made by the project for PRT (issue 17).

Two walls 2 m high and 0.1 m thick meeting in a corner at x = z = -1 (inner faces on x = -1 and
z = -1, 3 m long), and three stairs (0.3 m deep, 0.17 m rise, 1.2 m wide) climbing along +x
against the z wall from x = 0.4. Every part is a closed box with flat normals (24 vertices), so
no surface is seen from behind. Materials: warm white walls, gray steps. Regenerate with
  /usr/bin/python3 scripts/make_wall_corner.py assets/wall_corner.gltf
"""
import base64
import json
import struct
import sys


def box(lo, hi):
    """Positions, normals and indices of the axis-aligned box [lo, hi], faces outward."""
    faces = [  # (normal, axis, side): the face at lo/hi of `axis`
        ((1, 0, 0), 0, 1), ((-1, 0, 0), 0, 0), ((0, 1, 0), 1, 1),
        ((0, -1, 0), 1, 0), ((0, 0, 1), 2, 1), ((0, 0, -1), 2, 0)]
    positions, normals, indices = [], [], []
    for normal, axis, side in faces:
        u, v = [a for a in range(3) if a != axis]
        corners = []
        for cu, cv in ((0, 0), (1, 0), (1, 1), (0, 1)):
            p = [0.0, 0.0, 0.0]
            p[axis] = hi[axis] if side else lo[axis]
            p[u] = hi[u] if cu else lo[u]
            p[v] = hi[v] if cv else lo[v]
            corners.append(p)
        base = len(positions)
        positions += corners
        normals += [list(normal)] * 4
        # Wind counter-clockwise seen from outside: flip when (u x v) points inward.
        cross = [0, 0, 0]
        cross[3 - u - v] = 1 if (v - u) % 3 == 1 else -1
        outward = sum(c * n for c, n in zip(cross, normal)) > 0
        quad = [0, 1, 2, 0, 2, 3] if outward else [0, 2, 1, 0, 3, 2]
        indices += [base + i for i in quad]
    return positions, normals, indices


def main(path):
    parts = [  # (name, material, lo, hi)
        ("wall_x", 0, (-1.1, 0.0, -1.1), (-1.0, 2.0, 1.9)),
        ("wall_z", 0, (-1.0, 0.0, -1.1), (2.0, 2.0, -1.0)),
    ]
    for step in range(3):
        x0 = 0.4 + 0.3 * step
        parts.append((f"step_{step}", 1, (x0, 0.0, -1.0), (2.0, 0.17 * (step + 1), 0.2)))
    blob = bytearray()
    accessors, views, meshes, nodes = [], [], [], []
    for name, material, lo, hi in parts:
        positions, normals, indices = box(lo, hi)
        prims = {}
        for kind, data, fmt, comp, typ, target in (
                ("POSITION", positions, "3f", 5126, "VEC3", 34962),
                ("NORMAL", normals, "3f", 5126, "VEC3", 34962),
                ("indices", indices, "H", 5123, "SCALAR", 34963)):
            while len(blob) % 4:
                blob.append(0)
            offset = len(blob)
            for item in data:
                blob += struct.pack("<" + fmt, *(item if isinstance(item, list) else [item]))
            views.append({"buffer": 0, "byteOffset": offset, "byteLength": len(blob) - offset, "target": target})
            accessor = {"bufferView": len(views) - 1, "componentType": comp, "count": len(data), "type": typ}
            if kind == "POSITION":
                accessor["min"] = [min(p[i] for p in positions) for i in range(3)]
                accessor["max"] = [max(p[i] for p in positions) for i in range(3)]
            accessors.append(accessor)
            prims[kind] = len(accessors) - 1
        meshes.append({"name": name, "primitives": [{
            "attributes": {"POSITION": prims["POSITION"], "NORMAL": prims["NORMAL"]},
            "indices": prims["indices"], "material": material}]})
        nodes.append({"name": name, "mesh": len(meshes) - 1})
    gltf = {
        "asset": {"version": "2.0", "generator": "proxygi scripts/make_wall_corner.py"},
        "scene": 0,
        "scenes": [{"nodes": list(range(len(nodes)))}],
        "nodes": nodes,
        "meshes": meshes,
        "materials": [
            {"name": "wall", "pbrMetallicRoughness": {"baseColorFactor": [0.75, 0.7, 0.62, 1.0], "metallicFactor": 0.0}},
            {"name": "step", "pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.5, 0.5, 1.0], "metallicFactor": 0.0}}],
        "buffers": [{"byteLength": len(blob),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(bytes(blob)).decode()}],
        "bufferViews": views,
        "accessors": accessors,
    }
    with open(path, "w") as f:
        json.dump(gltf, f, indent=1)
        f.write("\n")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "assets/wall_corner.gltf")
