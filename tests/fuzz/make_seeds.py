#!/usr/bin/env python3
"""Writes the fuzz seed corpus (tests/fuzz/corpus/): small valid glTF/GLB files covering the
importer's features, and broken variants. Re-run after changing it; the output is committed."""
import base64, json, os, struct, sys, zlib

OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus")


def png_2x2():
    raw = b"".join(b"\x00" + bytes([255, 0, 0, 255, 0, 255, 0, 255]) for _ in range(2))
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", 2, 2, 8, 6, 0, 0, 0))
            + chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))


class Builder:
    def __init__(self):
        self.bin = bytearray()
        self.gltf = {"asset": {"version": "2.0"}, "buffers": [], "bufferViews": [], "accessors": []}

    def view(self, data, stride=None):
        while len(self.bin) % 4:
            self.bin += b"\0"
        view = {"buffer": 0, "byteOffset": len(self.bin), "byteLength": len(data)}
        if stride:
            view["byteStride"] = stride
        self.bin += data
        self.gltf["bufferViews"].append(view)
        return len(self.gltf["bufferViews"]) - 1

    def accessor(self, view, ctype, count, kind, **extra):
        acc = {"componentType": ctype, "count": count, "type": kind}
        if view is not None:
            acc["bufferView"] = view
        acc.update(extra)
        self.gltf["accessors"].append(acc)
        return len(self.gltf["accessors"]) - 1


def skinned(builder):
    b = builder
    positions = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (1, 1, 0)]
    normals = [(0, 0, 1)] * 4
    inter = b"".join(struct.pack("<3f3f", *p, *n) for p, n in zip(positions, normals))
    v = b.view(inter, stride=24)
    pos = b.accessor(v, 5126, 4, "VEC3", min=[0, 0, 0], max=[1, 1, 0])
    nrm = b.accessor(v, 5126, 4, "VEC3", byteOffset=12)
    uv = b.accessor(b.view(struct.pack("<8H", 0, 0, 65535, 0, 0, 65535, 65535, 65535)), 5123, 4, "VEC2", normalized=True)
    j0 = b.accessor(b.view(bytes([0, 1, 2, 0] * 4)), 5121, 4, "VEC4")
    w0 = b.accessor(b.view(bytes([128, 64, 32, 0] * 4)), 5121, 4, "VEC4", normalized=True)
    j1 = b.accessor(b.view(struct.pack("<16H", *([1, 2, 0, 0] * 4))), 5123, 4, "VEC4")
    w1 = b.accessor(b.view(struct.pack("<16f", *([0.03, 0.0, 0.0, 0.0] * 4))), 5126, 4, "VEC4")
    idx = b.accessor(b.view(struct.pack("<4H", 0, 1, 2, 3)), 5123, 4, "SCALAR")
    # Sparse morph target without bufferView: zeros with one displaced vertex.
    sp_i = b.view(struct.pack("<H", 3) + b"\0\0")
    sp_v = b.view(struct.pack("<3f", 0, 0, 0.5))
    morph = b.accessor(None, 5126, 4, "VEC3", sparse={"count": 1, "indices": {"bufferView": sp_i, "componentType": 5123}, "values": {"bufferView": sp_v}})
    ibm = b.accessor(b.view(b"".join(struct.pack("<16f", 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, -t, 0, 0, 1) for t in (0, 0.5, 1))), 5126, 3, "MAT4")
    times = b.accessor(b.view(struct.pack("<3f", 0.5, 1.0, 2.0)), 5126, 3, "SCALAR", min=[0.5], max=[2.0])
    rot = b.accessor(b.view(struct.pack("<12h", 0, 0, 0, 32767, 0, 23170, 0, 23170, 0, 32767, 0, 0)), 5122, 3, "VEC4", normalized=True)
    cub = b.accessor(b.view(struct.pack("<27f", *([0, 0, 0, 0, 1, 0, 0, 0, 0] * 3))), 5126, 9, "VEC3")
    scl = b.accessor(b.view(struct.pack("<9f", *([1, 1, 1] * 3))), 5126, 3, "VEC3")
    wts = b.accessor(b.view(bytes([0, 128, 255, 0])), 5121, 3, "SCALAR", normalized=True)
    g = b.gltf
    g["meshes"] = [{"primitives": [{"attributes": {"POSITION": pos, "NORMAL": nrm, "TEXCOORD_0": uv, "JOINTS_0": j0, "WEIGHTS_0": w0, "JOINTS_1": j1, "WEIGHTS_1": w1},
                                    "indices": idx, "mode": 5, "material": 0, "targets": [{"POSITION": morph}]}], "weights": [0.0]}]
    g["nodes"] = [{"name": "root", "children": [1, 4]}, {"name": "hip", "children": [2], "translation": [0, 0.5, 0]},
                  {"name": "spine", "children": [3], "rotation": [0, 0, 0, 1]}, {"name": "head", "scale": [1, 1, 1]},
                  {"name": "body", "mesh": 0, "skin": 0}]
    g["skins"] = [{"joints": [1, 2, 3], "inverseBindMatrices": ibm, "skeleton": 1}]
    g["animations"] = [{"name": "wave", "samplers": [{"input": times, "output": rot}, {"input": times, "output": cub, "interpolation": "CUBICSPLINE"},
                                                   {"input": times, "output": scl, "interpolation": "STEP"}, {"input": times, "output": wts}],
                        "channels": [{"sampler": 0, "target": {"node": 2, "path": "rotation"}}, {"sampler": 1, "target": {"node": 1, "path": "translation"}},
                                     {"sampler": 2, "target": {"node": 3, "path": "scale"}}, {"sampler": 3, "target": {"node": 4, "path": "weights"}}]}]
    g["materials"] = [{"pbrMetallicRoughness": {"baseColorFactor": [1, 0.5, 0.5, 1], "baseColorTexture": {"index": 0}}}]
    g["textures"] = [{"source": 0}]
    g["images"] = [{"uri": "data:image/png;base64," + base64.b64encode(png_2x2()).decode()}]
    g["scenes"] = [{"nodes": [0]}]
    g["scene"] = 0
    return b


def as_gltf(b, uri=None):
    g = json.loads(json.dumps(b.gltf))
    g["buffers"] = [{"byteLength": len(b.bin), "uri": uri or "data:application/octet-stream;base64," + base64.b64encode(bytes(b.bin)).decode()}]
    return json.dumps(g, separators=(",", ":")).encode()


def as_glb(b):
    g = json.loads(json.dumps(b.gltf))
    g["buffers"] = [{"byteLength": len(b.bin)}]
    text = json.dumps(g, separators=(",", ":")).encode()
    text += b" " * (-len(text) % 4)
    binary = bytes(b.bin) + b"\0" * (-len(b.bin) % 4)
    total = 12 + 8 + len(text) + 8 + len(binary)
    return (b"glTF" + struct.pack("<II", 2, total) + struct.pack("<I", len(text)) + b"JSON" + text
            + struct.pack("<I", len(binary)) + b"BIN\0" + binary)


def main():
    os.makedirs(OUT, exist_ok=True)
    seeds = {}
    b = skinned(Builder())
    seeds["skinned.gltf"] = as_gltf(b)
    seeds["skinned.glb"] = as_glb(b)
    seeds["truncated.glb"] = as_glb(b)[:200]
    g = json.loads(as_gltf(b))
    g["nodes"][3]["children"] = [1]
    seeds["cycle.gltf"] = json.dumps(g).encode()
    g = json.loads(as_gltf(b))
    g["buffers"][0]["uri"] = "..%2Fsecret.bin"
    seeds["traversal.gltf"] = json.dumps(g).encode()
    g = json.loads(as_gltf(b))
    g["accessors"][0]["count"] = 4000
    seeds["accessor_overflow.gltf"] = json.dumps(g).encode()
    ext = Builder()
    ext.gltf["buffers"] = [{"byteLength": 64, "uri": "a.bin"}]
    ext.gltf["bufferViews"] = [{"buffer": 0, "byteOffset": 16, "byteLength": 36}]
    ext.gltf["accessors"] = [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"}]
    ext.gltf["meshes"] = [{"primitives": [{"attributes": {"POSITION": 0}}]}]
    ext.gltf["nodes"] = [{"mesh": 0}]
    seeds["external.gltf"] = json.dumps(ext.gltf).encode()
    for name, data in seeds.items():
        with open(os.path.join(OUT, name), "wb") as f:
            f.write(data)
    print(f"wrote {len(seeds)} seeds to {OUT}")


if __name__ == "__main__":
    sys.exit(main())
