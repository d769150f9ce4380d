#!/usr/bin/env python3
"""Writes scenes/models/tiles.gltf (+ .bin and three PNG textures): Prism's own textured glTF
test model, a slab of coloured tiles with grooves, to exercise every texture path of the
renderer (sRGB base colour, metallic-roughness, tangent-space normal map). Standard library
only; run once, the output is committed. Usage: scripts/make_tiles_model.py [OUT_DIR]"""
import base64, json, math, os, struct, sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from png8 import png  # noqa: E402

N, TILES, GROOVE = 256, 4, 0.08  # texture size, tiles per side, groove width (fraction of a tile)
# sRGB-encoded tile colours (8-bit), saturated enough to show upsampling differences.
COLOURS = [(200, 40, 40), (230, 160, 30), (60, 150, 70), (40, 90, 180), (150, 60, 150),
           (240, 230, 210), (30, 160, 170), (120, 80, 50)]

def tile(x, y):
    u, v = (x + 0.5) / N * TILES, (y + 0.5) / N * TILES
    i, j = int(u), int(v)
    fu, fv = u - i, v - j
    d = min(fu, 1 - fu, fv, 1 - fv)  # distance to the tile's edge
    return i, j, fu, fv, d

def base_colour(x, y):
    i, j, _, _, d = tile(x, y)
    return (70, 70, 70) if d < GROOVE / 2 else COLOURS[(i + 3 * j) % len(COLOURS)]

def metallic_roughness(x, y):  # glTF: roughness in G, metallic in B
    i, j, _, _, d = tile(x, y)
    if d < GROOVE / 2:
        return (0, 255, 0)
    metal = (i + j) % 4 == 0
    return (0, 90 if metal else 140 + 20 * ((i * j) % 3), 255 if metal else 0)

def normal(x, y):  # bevelled tile edges in tangent space
    _, _, fu, fv, d = tile(x, y)
    nx = ny = 0.0
    bevel = GROOVE
    if d < bevel and d >= GROOVE / 2:
        if min(fu, 1 - fu) <= min(fv, 1 - fv):
            nx = -0.6 if fu < 0.5 else 0.6
        else:
            ny = -0.6 if fv < 0.5 else 0.6
    l = math.sqrt(nx * nx + ny * ny + 1)
    return tuple(int(round((c / l * 0.5 + 0.5) * 255)) for c in (nx, ny, 1.0))

def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "scenes", "models")
    os.makedirs(out, exist_ok=True)
    png(os.path.join(out, "tiles_base_colour.png"), N, N, base_colour)
    png(os.path.join(out, "tiles_metallic_roughness.png"), N, N, metallic_roughness)
    png(os.path.join(out, "tiles_normal.png"), N, N, normal)
    # A slab 2 × 0.1 × 2: the top face carries the tiles, the sides a strip of the same texture.
    s, t = 1.0, 0.05
    faces = [  # normal, tangent, corner origin, u axis, v axis
        ((0, 1, 0), (1, 0, 0), (-s, t, -s), (2 * s, 0, 0), (0, 0, 2 * s)),
        ((0, -1, 0), (1, 0, 0), (-s, -t, s), (2 * s, 0, 0), (0, 0, -2 * s)),
        ((0, 0, 1), (1, 0, 0), (-s, t, s), (2 * s, 0, 0), (0, -2 * t, 0)),
        ((0, 0, -1), (-1, 0, 0), (s, t, -s), (-2 * s, 0, 0), (0, -2 * t, 0)),
        ((1, 0, 0), (0, 0, -1), (s, t, s), (0, 0, -2 * s), (0, -2 * t, 0)),
        ((-1, 0, 0), (0, 0, 1), (-s, t, -s), (0, 0, 2 * s), (0, -2 * t, 0)),
    ]
    pos, nor, tan, uv, idx = [], [], [], [], []
    for n, tg, o, a, b in faces:
        base = len(pos)
        for cu, cv in ((0, 0), (1, 0), (1, 1), (0, 1)):
            pos.append(tuple(o[k] + cu * a[k] + cv * b[k] for k in range(3)))
            nor.append(n); tan.append(tg + (1.0,)); uv.append((cu, cv))
        # counter-clockwise seen from outside
        cross = [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
        ccw = sum(cross[k] * n[k] for k in range(3)) > 0
        idx += [base, base + 1, base + 2, base, base + 2, base + 3] if ccw else \
               [base, base + 2, base + 1, base, base + 3, base + 2]
    blob = b"".join(struct.pack("<3f", *p) for p in pos)
    blob += b"".join(struct.pack("<3f", *p) for p in nor)
    blob += b"".join(struct.pack("<4f", *p) for p in tan)
    blob += b"".join(struct.pack("<2f", *p) for p in uv)
    blob += b"".join(struct.pack("<I", i) for i in idx)
    open(os.path.join(out, "tiles.bin"), "wb").write(blob)
    nv = len(pos)
    views, off = [], 0
    for size in (12 * nv, 12 * nv, 16 * nv, 8 * nv, 4 * len(idx)):
        views.append({"buffer": 0, "byteOffset": off, "byteLength": size}); off += size
    gltf = {
        "asset": {"version": "2.0", "generator": "Prism scripts/make_tiles_model.py"},
        "scene": 0, "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0, "name": "tiles"}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TANGENT": 2, "TEXCOORD_0": 3},
                                    "indices": 4, "material": 0, "mode": 4}]}],
        "materials": [{"name": "tiles", "pbrMetallicRoughness": {
            "baseColorTexture": {"index": 0}, "metallicRoughnessTexture": {"index": 1},
            "baseColorFactor": [1, 1, 1, 1], "metallicFactor": 1.0, "roughnessFactor": 1.0},
            "normalTexture": {"index": 2}}],
        "textures": [{"source": 0}, {"source": 1}, {"source": 2}],
        "images": [{"uri": "tiles_base_colour.png"}, {"uri": "tiles_metallic_roughness.png"},
                   {"uri": "tiles_normal.png"}],
        "buffers": [{"uri": "tiles.bin", "byteLength": len(blob)}],
        "bufferViews": views,
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": nv, "type": "VEC3",
             "min": [-s, -t, -s], "max": [s, t, s]},
            {"bufferView": 1, "componentType": 5126, "count": nv, "type": "VEC3"},
            {"bufferView": 2, "componentType": 5126, "count": nv, "type": "VEC4"},
            {"bufferView": 3, "componentType": 5126, "count": nv, "type": "VEC2"},
            {"bufferView": 4, "componentType": 5125, "count": len(idx), "type": "SCALAR"},
        ],
    }
    open(os.path.join(out, "tiles.gltf"), "w").write(json.dumps(gltf, indent=1) + "\n")

main()
