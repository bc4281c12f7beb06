#!/usr/bin/env python3
"""Writes the engine benchmark's scenes into a folder (standard library only):

  room-box.scene.json            the reference room plus one box
  room-sphere-light.scene.json   the reference room, its light a sphere light, 16 shadow samples
  spheres-N.scene.json / .pov    N random spheres on a floor, one light (N = 10 ... 100,000),
                                 with its POV-Ray 3.7 twin (tests/oracle/scene_to_pov.py)
  mesh-N.obj, mesh-N.scene.json  a tessellated sphere of about N triangles in a room
                                 (N = 1,000 ... 1,000,000)
  mesh-N-primary.scene.json      the same mesh, depth 0, no shadows: primary rays + Lambert

Usage: python3 tests/bench/make-bench-scenes.py OUTDIR [--max-spheres N] [--max-triangles N]
"""
import json
import math
import os
import random
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
# The one scene -> POV-Ray mapping (tests/oracle/scene_to_pov.py) writes the twins.
sys.path.insert(0, os.path.join(ROOT, "tests", "oracle"))
sys.path.insert(0, os.path.join(ROOT, "tests", "bench", "lib"))
import scene_to_pov  # noqa: E402
from sphere_floor import side_for, sphere_floor  # noqa: E402


def reference_room():
    with open(os.path.join(ROOT, "scenes", "reference-room.scene.json")) as f:
        return json.load(f)


def write_json(path, doc):
    with open(path, "w") as f:
        json.dump(doc, f, indent=1)


def room_box(out):
    doc = reference_room()
    doc["materials"].append({"name": "box paint", "color": [0.6, 0.5, 0.9], "diffuse": 0.9})
    doc["objects"].append({"name": "box", "type": "box", "min": [-0.6, 0.0, -0.6],
                           "max": [0.6, 1.2, 0.6], "material": "box paint",
                           "translate": [-2.2, 0, -6.5], "rotate": [0, 30, 0]})
    write_json(os.path.join(out, "room-box.scene.json"), doc)


def room_sphere_light(out):
    doc = reference_room()
    light = doc["lights"][0]
    light["type"] = "sphere"
    light["radius"] = 0.4
    doc["render"]["shadow_samples"] = 16
    write_json(os.path.join(out, "room-sphere-light.scene.json"), doc)


def spheres(out, n, rng):
    """N spheres scattered over a floor, seen from above at an angle, one point light."""
    side = side_for(n)
    doc = sphere_floor(range(n), rng, side,
                       camera={"position": [0, 0.45 * side, 0.55 * side], "target": [0, 0, 0]},
                       light=[0.3 * side, side, 0.2 * side], ambient=0.05)
    write_json(os.path.join(out, "spheres-%d.scene.json" % n), doc)
    with open(os.path.join(out, "spheres-%d.pov" % n), "w") as f:
        f.write(scene_to_pov.convert(doc, out))


def mesh(out, triangles):
    """A UV sphere of about `triangles` triangles, as an OBJ, in a small room."""
    rings = max(3, int(math.sqrt(triangles / 2)))
    segments = max(3, triangles // (2 * rings))
    path = os.path.join(out, "mesh-%d.obj" % triangles)
    with open(path, "w") as f:
        for i in range(rings + 1):
            theta = math.pi * i / rings
            for j in range(segments):
                phi = 2 * math.pi * j / segments
                f.write("v %.6f %.6f %.6f\n" % (math.sin(theta) * math.cos(phi), math.cos(theta),
                                               math.sin(theta) * math.sin(phi)))
        for i in range(rings):
            for j in range(segments):
                a = i * segments + j + 1
                b = i * segments + (j + 1) % segments + 1
                c, d = a + segments, b + segments
                f.write("f %d %d %d\nf %d %d %d\n" % (a, c, b, b, c, d))
    base = {
        "format": "raystudio-scene", "version": 1,
        "camera": {"position": [0, 1.5, 4.2], "target": [0, 1.2, 0], "up": [0, 1, 0], "fov_y": 50},
        "render": {"width": 1280, "height": 720, "max_depth": 3, "shadow_samples": 1,
                   "ambient": [0.06, 0.06, 0.06]},
        "materials": [{"name": "wall", "color": [0.8, 0.8, 0.75], "diffuse": 0.9},
                      {"name": "clay", "color": [0.85, 0.45, 0.3], "diffuse": 0.9}],
        "lights": [{"name": "lamp", "type": "point", "position": [1.5, 3.5, 2.5]}],
        "objects": [
            {"name": "floor", "type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "wall"},
            {"name": "back", "type": "plane", "point": [0, 0, -3], "normal": [0, 0, 1], "material": "wall"},
            {"name": "mesh", "type": "mesh", "file": os.path.basename(path), "smooth_normals": False,
             "material": "clay", "translate": [0, 1.2, 0], "scale": 1.2},
        ],
    }
    write_json(os.path.join(out, "mesh-%d.scene.json" % triangles), base)
    # Primary rays and Lambert only: what Embree's rtcIntersect1 alone is compared with.
    base["render"]["max_depth"] = 0
    base["render"]["shadow_samples"] = 0
    base["objects"] = [base["objects"][2]]
    base["objects"][0]["scale"] = 2.0
    write_json(os.path.join(out, "mesh-%d-primary.scene.json" % triangles), base)


def main(argv):
    if len(argv) < 2 or argv[1] in ("-h", "--help"):
        print(__doc__)
        return 0 if len(argv) >= 2 else 2
    out = argv[1]
    max_spheres = 100000
    max_triangles = 1000000
    args = argv[2:]
    while args:
        if args[0] == "--max-spheres":
            max_spheres = int(args[1])
        elif args[0] == "--max-triangles":
            max_triangles = int(args[1])
        else:
            print("make-bench-scenes.py: unknown option " + args[0], file=sys.stderr)
            return 2
        args = args[2:]
    os.makedirs(out, exist_ok=True)
    rng = random.Random(7)
    room_box(out)
    room_sphere_light(out)
    n = 10
    while n <= max_spheres:
        spheres(out, n, rng)
        n *= 10
    t = 1000
    while t <= max_triangles:
        mesh(out, t)
        t *= 10
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
