#!/usr/bin/env python3
"""Writes PRT's third example scene (issue 14): a ~100k-vertex self-shadowing glTF model under an
HDR environment map. scenes/models/prt_rock.glb is a rock: a UV sphere of 225 × 449 vertices
whose radius is displaced by ridged value noise, deep enough that its ridges shadow its valleys,
with smooth normals. scenes/models/prt_sky.hdr is a 256 × 128 equirectangular Radiance map (row
0 at the zenith): a blue sky gradient, a warm sun-lit patch of sky and a dark brown ground.
Deterministic: the same files every run. No dependencies beyond Python 3.

Usage: scripts/make_prt_rock.py
"""
import json
import math
import pathlib
import struct

root = pathlib.Path(__file__).resolve().parent.parent
models = root / "scenes/models"
models.mkdir(parents=True, exist_ok=True)

STACKS, SLICES = 224, 448  # (224 + 1) × (448 + 1) = 101 025 vertices


def lattice(ix, iy, iz, seed):
    h = (ix * 73856093 ^ iy * 19349663 ^ iz * 83492791 ^ seed * 2654435761) & 0xFFFFFFFF
    h = ((h >> 13) ^ h) * 1274126177 & 0xFFFFFFFF
    return (h & 0xFFFF) / 32767.5 - 1.0


def value_noise(x, y, z, seed):
    fx, fy, fz = math.floor(x), math.floor(y), math.floor(z)
    tx, ty, tz = x - fx, y - fy, z - fz
    sx, sy, sz = (t * t * (3 - 2 * t) for t in (tx, ty, tz))
    total = 0.0
    for dx in (0, 1):
        for dy in (0, 1):
            for dz in (0, 1):
                w = (sx if dx else 1 - sx) * (sy if dy else 1 - sy) * (sz if dz else 1 - sz)
                total += w * lattice(int(fx) + dx, int(fy) + dy, int(fz) + dz, seed)
    return total


def radius(d):
    r, amplitude, frequency = 1.0, 0.22, 1.6
    for octave in range(5):
        n = value_noise(d[0] * frequency, d[1] * frequency, d[2] * frequency, 7 + octave)
        r += amplitude * (1.0 - 2.0 * abs(n))  # ridged: sharp crests, rounded valleys
        amplitude *= 0.5
        frequency *= 2.1
    return r


positions = []
for i in range(STACKS + 1):
    theta = math.pi * i / STACKS
    for j in range(SLICES + 1):
        phi = 2 * math.pi * j / SLICES
        d = (math.sin(theta) * math.cos(phi), math.cos(theta), math.sin(theta) * math.sin(phi))
        r = radius(d)
        positions.append((d[0] * r, d[1] * r * 0.8, d[2] * r))  # a little flattened

indices = []
for i in range(STACKS):
    for j in range(SLICES):
        a, b = i * (SLICES + 1) + j, (i + 1) * (SLICES + 1) + j
        if i != 0:
            indices += (a, a + 1, b)  # counter-clockwise seen from outside (glTF's front faces)
        if i != STACKS - 1:
            indices += (a + 1, b + 1, b)

# Smooth normals: area-weighted face normals summed per vertex; the seam column (j = 0 and
# j = SLICES) and the poles share their sums so that no crease shows.
normals = [[0.0, 0.0, 0.0] for _ in positions]
for t in range(0, len(indices), 3):
    ia, ib, ic = indices[t:t + 3]
    a, b, c = positions[ia], positions[ib], positions[ic]
    u = (b[0] - a[0], b[1] - a[1], b[2] - a[2])
    v = (c[0] - a[0], c[1] - a[1], c[2] - a[2])
    n = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
    for i in (ia, ib, ic):
        for k in range(3):
            normals[i][k] += n[k]
for i in range(STACKS + 1):
    first, last = i * (SLICES + 1), i * (SLICES + 1) + SLICES
    for k in range(3):
        normals[first][k] = normals[last][k] = normals[first][k] + normals[last][k]
for row in (0, STACKS):
    cells = range(row * (SLICES + 1), (row + 1) * (SLICES + 1))
    pole = [sum(normals[i][k] for i in cells) for k in range(3)]
    for i in cells:
        normals[i] = list(pole)
for n in normals:
    length = math.sqrt(n[0] ** 2 + n[1] ** 2 + n[2] ** 2) or 1.0
    n[0], n[1], n[2] = n[0] / length, n[1] / length, n[2] / length

position_bytes = b"".join(struct.pack("<3f", *p) for p in positions)
normal_bytes = b"".join(struct.pack("<3f", *n) for n in normals)
index_bytes = struct.pack(f"<{len(indices)}I", *indices)
binary = position_bytes + normal_bytes + index_bytes
lo = [min(p[k] for p in positions) for k in range(3)]
hi = [max(p[k] for p in positions) for k in range(3)]
gltf = {
    "asset": {"version": "2.0", "generator": "scripts/make_prt_rock.py"},
    "scene": 0,
    "scenes": [{"nodes": [0]}],
    "nodes": [{"mesh": 0, "name": "rock"}],
    "meshes": [{"name": "rock", "primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1}, "indices": 2}]}],
    "buffers": [{"byteLength": len(binary)}],
    "bufferViews": [
        {"buffer": 0, "byteOffset": 0, "byteLength": len(position_bytes), "target": 34962},
        {"buffer": 0, "byteOffset": len(position_bytes), "byteLength": len(normal_bytes), "target": 34962},
        {"buffer": 0, "byteOffset": len(position_bytes) + len(normal_bytes), "byteLength": len(index_bytes),
         "target": 34963},
    ],
    "accessors": [
        {"bufferView": 0, "componentType": 5126, "count": len(positions), "type": "VEC3", "min": lo, "max": hi},
        {"bufferView": 1, "componentType": 5126, "count": len(normals), "type": "VEC3"},
        {"bufferView": 2, "componentType": 5125, "count": len(indices), "type": "SCALAR"},
    ],
}
text = json.dumps(gltf, separators=(",", ":")).encode()
text += b" " * (-len(text) % 4)
glb = struct.pack("<III", 0x46546C67, 2, 12 + 8 + len(text) + 8 + len(binary))
glb += struct.pack("<II", len(text), 0x4E4F534A) + text + struct.pack("<II", len(binary), 0x004E4942) + binary
(models / "prt_rock.glb").write_bytes(glb)


def rgbe(r, g, b):
    m = max(r, g, b)
    if m < 1e-32:
        return bytes(4)
    mantissa, exponent = math.frexp(m)
    scale = mantissa * 256.0 / m
    return bytes((int(r * scale), int(g * scale), int(b * scale), exponent + 128))


W, H = 256, 128
sun = (math.cos(math.radians(35)) * math.cos(math.radians(40)), math.sin(math.radians(35)),
       math.cos(math.radians(35)) * math.sin(math.radians(40)))
pixels = bytearray()
for y in range(H):
    elevation = math.pi / 2 - math.pi * (y + 0.5) / H
    for x in range(W):
        azimuth = 2 * math.pi * (x + 0.5) / W
        d = (math.cos(elevation) * math.cos(azimuth), math.sin(elevation), math.cos(elevation) * math.sin(azimuth))
        if elevation < 0:
            colour = (0.16, 0.11, 0.07)  # dark brown ground
        else:
            t = elevation / (math.pi / 2)
            colour = (0.35 + 0.25 * (1 - t), 0.55 + 0.15 * (1 - t), 0.95)
            glow = max(0.0, sum(a * b for a, b in zip(d, sun))) ** 64  # a warm, bright patch around the sun
            colour = (colour[0] + 30 * glow, colour[1] + 24 * glow, colour[2] + 14 * glow)
        pixels += rgbe(*colour)
header = f"#?RADIANCE\n# scripts/make_prt_rock.py\nFORMAT=32-bit_rle_rgbe\n\n-Y {H} +X {W}\n".encode()
(models / "prt_sky.hdr").write_bytes(header + bytes(pixels))
print(f"prt_rock.glb: {len(positions)} vertices, {len(indices) // 3} triangles, {len(glb)} bytes; prt_sky.hdr")
