#!/usr/bin/env python3
"""Writes the PRT example scenes (scenes/prt_macbeth.json, prt_sky.json, prt_metamers.json) and their
reflectances (scenes/prt/*.csv): the 24 ColorChecker spectra from data/colorchecker24.csv, one
file a patch, and the light-skin metamer from `prism colour metamer` (PRISM: the prism binary).

Usage: scripts/make_prt_scenes.py [PRISM]   (default build/release/app/prism)
"""
import csv
import json
import pathlib
import re
import subprocess
import sys

root = pathlib.Path(__file__).resolve().parent.parent
prism = sys.argv[1] if len(sys.argv) > 1 else str(root / "build/release/app/prism")
out = root / "scenes/prt"
out.mkdir(parents=True, exist_ok=True)


def slug(name):
    return re.sub(r"[^a-z0-9]+", "_", name.split(" (")[0].lower()).strip("_")


with open(root / "data/colorchecker24.csv") as f:
    rows = list(csv.reader(f))
names = rows[0][1:]
patches = []
for column, name in enumerate(names, start=1):
    path = out / f"{column:02d}_{slug(name)}.csv"
    with open(path, "w") as f:
        f.write("wavelength_nm,reflectance\n")
        for r in rows[1:]:
            f.write(f"{r[0]},{r[column]}\n")
    patches.append((slug(name), path.relative_to(root / "scenes").as_posix()))

subprocess.run([prism, "colour", "metamer", "--reflectance", "light skin", "--match", "D65", "--target", "A",
                "-o", str(out / "light_skin_metamer_d65.csv")], check=True, stdout=subprocess.DEVNULL)


def write(name, scene):
    (root / "scenes" / name).write_text(json.dumps(scene, indent=2, ensure_ascii=False) + "\n")


# Macbeth: the 24 patches as spheres in chart order (6 × 4) on a grey floor, all PRT objects so
# that each sphere shades the floor and its neighbours' feet, under an F4 overcast sky.
materials = {name: {"reflectance": {"csv": csv_path}} for name, csv_path in patches}
materials["floor"] = {"reflectance": {"csv": patches[21][1]}}  # neutral 5
# PRT shades per vertex: the floor is a flat height field fine enough to carry the spheres' shadows.
objects = [{"heightfield": {"centre": [0, 0, 0], "size": [6.4, 4.4], "resolution": 96, "amplitude": 0},
            "material": "floor", "name": "floor", "technique": "prt"}]
for i, (name, _) in enumerate(patches):
    row, column = divmod(i, 6)
    objects.append({"sphere": {"centre": [round(-2.5 + column, 3), 0.42, round(-1.5 + row, 3)], "radius": 0.42,
                               "segments": 32},
                    "material": name, "name": name, "technique": "prt"})
write("prt_macbeth.json", {
    "description": "Spectral PRT (Schwenk et al.): the 24 ColorChecker spectra on spheres over a grey floor, "
                   "self-shadowing, under an F4 overcast sky; m = 8 basis functions.",
    "camera": {"position": [0, 5.2, 4.6], "target": [0, 0, -0.1], "up": [0, 1, 0], "fov_deg": 45, "near": 0.1,
               "far": 50, "ev100": 10.0},
    "materials": materials,
    "objects": objects,
    "background": {"colour": [0.6, 0.6, 0.6], "luminance": 300},
    "prt": {"environment": {"illuminant": "F4", "shape": "sky", "luminance": 1000}, "basis": 8, "mode": "spectral",
            "samples": 256},
})

# The same chart under Prism's spectral sky, the sun 15° high: the sky through PRT's basis, the sun
# a light of the scene (shadow-mapped, per wavelength).
write("prt_sky.json", {
    "description": "Spectral PRT under Prism's spectral sky (issue 14): the 24 ColorChecker spectra on spheres over "
                   "a grey floor, self-shadowing, lit by the atmosphere's sky (tabulated at PRT's 81 wavelengths, "
                   "projected on SH-5) and its sun 15° above the horizon, a light of the scene (shadow-mapped, per "
                   "wavelength). m = 8 basis functions; `set prt.sun-elevation DEG` moves the sun in the viewer.",
    "camera": {"position": [0, 5.2, 4.6], "target": [0, 0, -0.1], "up": [0, 1, 0], "fov_deg": 45, "near": 0.1,
               "far": 50, "ev100": 13.0},
    "materials": materials,
    "objects": objects,
    "background": {"colour": [0.4, 0.55, 0.85], "luminance": 4000},
    "prt": {"environment": {"atmosphere": {"sun": {"elevation": 15, "azimuth": 120}}}, "basis": 8,
            "mode": "spectral", "samples": 256},
})

# Metamers (the paper's "Metacow" idea): two halves of one shape, touching spheres, carry light
# skin and its D65 metamer; under A they part, under D65 they match (--set
# prt.environment.illuminant=D65).
write("prt_metamers.json", {
    "description": "Spectral PRT metamers: two touching spheres carry light skin (left) and a metamer of it under "
                   "D65 (right), lit by an A sky, where they differ (ΔE00 ≈ 28); with --set "
                   "prt.environment.illuminant=D65 they match.",
    "camera": {"position": [0, 2.2, 3.6], "target": [0, 0.5, 0], "up": [0, 1, 0], "fov_deg": 40, "near": 0.1,
               "far": 50, "ev100": 10.0},
    "materials": {"patch": {"reflectance": {"csv": patches[1][1]}},
                  "metamer": {"reflectance": {"csv": "prt/light_skin_metamer_d65.csv"}},
                  "floor": {"reflectance": {"csv": patches[20][1]}}},  # neutral 6.5
    "objects": [
        {"heightfield": {"centre": [0, 0, 0], "size": [4, 4], "resolution": 64, "amplitude": 0}, "material": "floor",
         "name": "floor", "technique": "prt"},
        {"sphere": {"centre": [-0.55, 0.55, 0], "radius": 0.55, "segments": 48}, "material": "patch",
         "name": "patch half", "technique": "prt"},
        {"sphere": {"centre": [0.55, 0.55, 0], "radius": 0.55, "segments": 48}, "material": "metamer",
         "name": "metamer half", "technique": "prt"},
    ],
    "background": {"colour": [0.6, 0.6, 0.6], "luminance": 300},
    "prt": {"environment": {"illuminant": "A", "shape": "sky", "luminance": 1000}, "basis": 8, "mode": "spectral",
            "samples": 256},
})
