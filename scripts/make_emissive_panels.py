#!/usr/bin/env python3
"""Writes render/tests/emissive_panels.gltf and its texture emissive_sign.png: the fixture of glTF's
emission (render_test's EmittingMaterials, the GPU–CPU twin, the path tracer's test).

Two black unit quads facing +z, side by side: "glow" emits its emissiveFactor (0.2, 0.5, 1.0) at
KHR_materials_emissive_strength 2, untextured, so every pixel of it is one known colour; "sign"
emits (1.0, 0.8, 0.3) times a 4 × 4 sRGB texture of sixteen colours, black among them.

Usage: scripts/make_emissive_panels.py
"""
import base64
import json
import pathlib
import struct

from png8 import png

OUT = pathlib.Path(__file__).resolve().parent.parent / "render" / "tests"

# Sixteen texels, row 0 at the top: greys, primaries, secondaries, a few mixed, and black.
TEXELS = [
    (255, 255, 255), (200, 200, 200), (128, 128, 128), (0, 0, 0),
    (255, 0, 0), (0, 255, 0), (0, 0, 255), (255, 255, 0),
    (0, 255, 255), (255, 0, 255), (255, 128, 0), (128, 0, 255),
    (60, 180, 75), (230, 25, 75), (70, 240, 240), (250, 190, 212),
]


def quad(x0, x1):
    """A quad in z = 0 from x0 to x1, y 0 to 1, facing +z: positions, normals, uvs (v down)."""
    corners = [(x0, 0.0), (x1, 0.0), (x1, 1.0), (x0, 1.0)]
    positions = [(x, y, 0.0) for x, y in corners]
    normals = [(0.0, 0.0, 1.0)] * 4
    uvs = [((x - x0) / (x1 - x0), 1.0 - y) for x, y in corners]
    return positions, normals, uvs


def main():
    blob = b""
    views, accessors, primitives = [], [], []

    def add(data, fmt, count, kind, target, minmax=None):
        nonlocal blob
        views.append({"buffer": 0, "byteOffset": len(blob), "byteLength": len(data), "target": target})
        accessor = {"bufferView": len(views) - 1, "componentType": 5126 if fmt == "f" else 5123,
                    "count": count, "type": kind}
        if minmax:
            accessor["min"], accessor["max"] = minmax
        accessors.append(accessor)
        blob += data + b"\0" * (-len(data) % 4)
        return len(accessors) - 1

    for material, (x0, x1) in enumerate([(-1.1, -0.1), (0.1, 1.1)]):
        positions, normals, uvs = quad(x0, x1)
        flat = [c for p in positions for c in p]
        p = add(struct.pack("<12f", *flat), "f", 4, "VEC3", 34962,
                ([x0, 0.0, 0.0], [x1, 1.0, 0.0]))
        n = add(struct.pack("<12f", *[c for v in normals for c in v]), "f", 4, "VEC3", 34962)
        t = add(struct.pack("<8f", *[c for v in uvs for c in v]), "f", 4, "VEC2", 34962)
        i = add(struct.pack("<6H", 0, 1, 2, 0, 2, 3), "H", 6, "SCALAR", 34963)
        primitives.append({"attributes": {"POSITION": p, "NORMAL": n, "TEXCOORD_0": t}, "indices": i,
                           "material": material})

    black = {"baseColorFactor": [0.0, 0.0, 0.0, 1.0], "metallicFactor": 0.0, "roughnessFactor": 1.0}
    gltf = {
        "asset": {"version": "2.0", "generator": "scripts/make_emissive_panels.py"},
        "extensionsUsed": ["KHR_materials_emissive_strength"],
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": primitives}],
        "materials": [
            {"name": "glow", "pbrMetallicRoughness": black, "emissiveFactor": [0.2, 0.5, 1.0],
             "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 2.0}}},
            {"name": "sign", "pbrMetallicRoughness": black, "emissiveFactor": [1.0, 0.8, 0.3],
             "emissiveTexture": {"index": 0}},
        ],
        "textures": [{"source": 0}],
        "images": [{"uri": "emissive_sign.png"}],
        "buffers": [{"byteLength": len(blob),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(blob).decode()}],
        "bufferViews": views,
        "accessors": accessors,
    }
    (OUT / "emissive_panels.gltf").write_text(json.dumps(gltf, indent=1) + "\n")
    png(OUT / "emissive_sign.png", 4, 4, lambda x, y: TEXELS[4 * y + x])


if __name__ == "__main__":
    main()
