#!/usr/bin/env python3
"""Writes the reef scene's textures: scenes/models/reef_sand.png (tileable rippled sand) and
scenes/models/reef_coral.png (tileable polyp spots on coral tissue), 8-bit sRGB. Standard library
only; run once, the output is committed. Usage: scripts/make_reef_textures.py [OUT_DIR]"""
import math, os, sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from png8 import png  # noqa: E402

N = 128

def lattice(i, j, seed):  # a value in [0, 1) per lattice point, periodic over `period` cells
    h = (i * 374761393 + j * 668265263 + seed * 982451653) & 0xFFFFFFFF
    h = ((h ^ (h >> 13)) * 1274126177) & 0xFFFFFFFF
    return ((h ^ (h >> 16)) & 0xFFFF) / 65536.0

def noise(x, y, period, seed):  # tileable value noise, x and y in cells
    i, j = int(math.floor(x)), int(math.floor(y))
    fx, fy = x - i, y - j
    sx, sy = fx * fx * (3 - 2 * fx), fy * fy * (3 - 2 * fy)
    v = lambda a, b: lattice(a % period, b % period, seed)
    top = v(i, j) + (v(i + 1, j) - v(i, j)) * sx
    bottom = v(i, j + 1) + (v(i + 1, j + 1) - v(i, j + 1)) * sx
    return top + (bottom - top) * sy

def clamp8(v):
    return max(0, min(255, int(round(v))))

def sand(x, y):
    u, v = x / N, y / N
    ripples = 0.5 + 0.5 * math.sin(2 * math.pi * (3 * u + 0.35 * math.sin(2 * math.pi * v)))
    grain = noise(u * 32, v * 32, 32, 1)
    blotch = noise(u * 4, v * 4, 4, 2)
    t = 0.55 * ripples + 0.25 * grain + 0.2 * blotch
    return (clamp8(170 + 60 * t), clamp8(150 + 50 * t), clamp8(110 + 40 * t))

def coral(x, y):
    u, v = x / N, y / N
    cells = 8
    cu, cv = u * cells, v * cells
    best = 9.0
    for di in (-1, 0, 1):
        for dj in (-1, 0, 1):
            i, j = int(math.floor(cu)) + di, int(math.floor(cv)) + dj
            px = i + 0.2 + 0.6 * lattice(i % cells, j % cells, 3)
            py = j + 0.2 + 0.6 * lattice(i % cells, j % cells, 4)
            best = min(best, math.hypot(cu - px, cv - py))
    polyp = max(0.0, 1.0 - best / 0.32)
    tissue = noise(u * 16, v * 16, 16, 5)
    # Tissue a saturated magenta-purple, polyps a pale yellow.
    r = (150 + 40 * tissue) * (1 - polyp) + 245 * polyp
    g = (40 + 30 * tissue) * (1 - polyp) + 225 * polyp
    b = (120 + 40 * tissue) * (1 - polyp) + 120 * polyp
    return (clamp8(r), clamp8(g), clamp8(b))

out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "scenes", "models")
png(os.path.join(out, "reef_sand.png"), N, N, sand)
png(os.path.join(out, "reef_coral.png"), N, N, coral)
