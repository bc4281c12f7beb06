#!/usr/bin/env python3
"""Writes the POV-Ray 3.7 twin of a RayStudio scene (standard library only).

Usage: python3 tests/oracle/scene_to_pov.py SCENE.scene.json OUT.pov [--width W] [--height H]
                                           [--shadow-samples N]
       (W x H sets the aspect ratio of the camera, the scene's render size otherwise; N
       overrides render.shadow_samples, as raystudio-cli's --shadow-samples does.)
Render the twin as the oracle test does:
       povray +W160 +H90 -D -A +FE +OOUT.exr OUT.pov     (linear EXR, one sample per pixel)

This file is the one place where a RayStudio scene becomes a POV-Ray scene: the oracle tests
(tests/oracle/) and the benchmark twins (tests/bench/make-bench-scenes.py) both use it.

How the illumination equation of scenes/FORMAT.md maps to POV-Ray:

  ours:  local  = I_a * color * kd + sum_l vis/S * I_l * C_l * (kd * color * N.L + ks * (R.V)^n)
         result = (1 - kr - kt) * local + kr * trace(refl) + kt * (F * trace(refl) + (1-F) * trace(refr))

- Coordinates: ours are right-handed (the camera looks down -z), POV-Ray's left-handed. Every
  point and direction is written with z negated, and every object matrix M as F M F with
  F = diag(1, 1, -1), so +x stays right and +y up and both programs see the same picture.
- Camera: POV-Ray's `angle` is the horizontal field of view: 2 atan(tan(fov_y / 2) * W / H).
  Orthographic: `right` and `up` are the visible width and height (ortho_height * W / H and
  ortho_height). Both sample pixel centres (+A off), as we do with supersampling 1.
- Ambient: `ambient_light` is the scene's `ambient` (I_a); POV-Ray multiplies a finish's
  `ambient` by the pigment and by ambient_light, so each finish's `ambient` is kd * (1 - kr - kt).
- Lambert and Phong: POV-Ray's diffuse is `diffuse` * pigment * N.L * light, its phong is
  `phong` * (R.L)^phong_size * light, uncoloured, the same products as ours. Both are written
  pre-multiplied by (1 - kr - kt), the share our equation leaves the local term (POV-Ray adds
  reflection on top of the surface's own colour).
- Lights: no `fade_power` (no fall-off in both); colour = intensity * color. A sphere light is an
  `area_light` disc of the sphere's diameter facing each shading point (`circular orient`),
  S x S samples with S = ceil(sqrt(shadow_samples)): our samples are stratified points on the
  same disc. shadow_samples 0 gives every object `no_shadow` (a `shadowless` light would
  also lose its Phong highlights in POV-Ray).
- Mirror: `reflection { kr }` adds kr * trace(refl) on top, as ours.
- Glass (kt > 0): `reflection { kr + kt R0, kr + kt falloff 5 }` is kr + kt * (R0 + (1 - R0)
  (1 - cos)^5), Schlick's F exactly (not POV-Ray's `fresnel`, which is the full Fresnel
  equation); the pigment's `transmit` is kt and `conserve_energy` takes the reflected share
  out of the transmitted one, leaving kt * (1 - F) * trace(refr). Inside a body the
  interior's ior is inverted as ours is. Total internal reflection sends the refracted part
  into the reflected ray in both.
- Shadows: ours treat every surface as opaque; POV-Ray lets light through a transmitting
  object. So a glass object gets `no_shadow` and an opaque twin (`no_image no_reflection`)
  casts its shadow.
- Depth: our max_depth counts bounces, POV-Ray's max_trace_level counts the camera ray too:
  level = max_depth + 1. Both return black past it. adc_bailout is our min_weight.
- Geometry: sphere, plane, box, rectangle (two triangles), mesh (mesh2 from the OBJ file with
  the per-vertex average of unit face normals when smooth_normals, as assimp's
  GenSmoothNormals computes them). Meshes are read from OBJ only (the bundled ones are OBJ).

Where the two differ on purpose (so the oracle's tolerances, or an analytic test, cover it):
- POV-Ray shades an area light with the direction to its centre and varies only visibility
  over the samples; ours takes N.L per sample. Its samples are a regular grid, ours jittered.
- POV-Ray's own surface offsets and intersection precision differ from ours at grazing hits.
"""
import json
import math
import os
import sys

DEFAULT_MATERIAL = {"color": [0.8, 0.8, 0.8], "diffuse": 1.0, "specular": 0.0, "shininess": 32.0,
                    "reflectivity": 0.0, "transparency": 0.0, "ior": 1.5}


def v3(p):
    """A point or direction of ours in POV-Ray's left-handed frame."""
    return "<%.9g, %.9g, %.9g>" % (p[0], p[1], -p[2])


def rgb(c):
    return "rgb <%.9g, %.9g, %.9g>" % tuple(c)


# 4x4 matrices as lists of rows, acting on column vectors (as glm does).
def matmul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(4)) for j in range(4)] for i in range(4)]


def translation(t):
    return [[1, 0, 0, t[0]], [0, 1, 0, t[1]], [0, 0, 1, t[2]], [0, 0, 0, 1]]


def rotation(axis, degrees):
    c, s = math.cos(math.radians(degrees)), math.sin(math.radians(degrees))
    if axis == 0:
        return [[1, 0, 0, 0], [0, c, -s, 0], [0, s, c, 0], [0, 0, 0, 1]]
    if axis == 1:
        return [[c, 0, s, 0], [0, 1, 0, 0], [-s, 0, c, 0], [0, 0, 0, 1]]
    return [[c, -s, 0, 0], [s, c, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]


def object_matrix(o):
    """Our Transform::matrix(): translate * Rz * Ry * Rx * scale."""
    scale = o.get("scale", 1.0)
    if not isinstance(scale, list):
        scale = [scale] * 3
    r = o.get("rotate", [0, 0, 0])
    m = translation(o.get("translate", [0, 0, 0]))
    m = matmul(m, rotation(2, r[2]))
    m = matmul(m, rotation(1, r[1]))
    m = matmul(m, rotation(0, r[0]))
    return matmul(m, [[scale[0], 0, 0, 0], [0, scale[1], 0, 0], [0, 0, scale[2], 0], [0, 0, 0, 1]])


def pov_matrix(m):
    """F m F with F = diag(1, 1, -1), in POV-Ray's row-vector `matrix` order."""
    f = [1, 1, -1]
    a = [[m[i][j] * f[i] * f[j] for j in range(3)] for i in range(3)]
    t = [m[0][3], m[1][3], -m[2][3]]
    cols = [a[0][0], a[1][0], a[2][0], a[0][1], a[1][1], a[2][1], a[0][2], a[1][2], a[2][2]]
    return "matrix <%s>" % ", ".join("%.9g" % x for x in cols + t)


def is_identity(o):
    s = o.get("scale", 1.0)
    return (o.get("translate", [0, 0, 0]) == [0, 0, 0] and o.get("rotate", [0, 0, 0]) == [0, 0, 0]
            and (s == 1 or s == [1, 1, 1]))


def material_block(m, scene_ambient_is_zero):
    kr, kt = m["reflectivity"], m["transparency"]
    local = 1.0 - kr - kt
    kd, ks = m["diffuse"] * local, m["specular"] * local
    finish = ["ambient %.9g" % (0.0 if scene_ambient_is_zero else m["diffuse"] * local),
              "diffuse %.9g" % kd]
    if ks > 0:
        finish.append("phong %.9g phong_size %.9g" % (ks, m["shininess"]))
    if kt > 0:
        r0 = ((1.0 - m["ior"]) / (1.0 + m["ior"])) ** 2
        finish.append("reflection { %.9g, %.9g falloff 5 } conserve_energy" % (kr + kt * r0, kr + kt))
        # POV-Ray scales the surface's own colour by (1 - transmit); ours by (1 - kr - kt)
        # already, so the finish above is divided back.
        scale = 1.0 / (1.0 - kt) if kt < 1.0 else 0.0
        finish[0] = "ambient %.9g" % (0.0 if scene_ambient_is_zero else m["diffuse"] * local * scale)
        finish[1] = "diffuse %.9g" % (kd * scale)
        if ks > 0:
            finish[2] = "phong %.9g phong_size %.9g" % (ks * scale, m["shininess"])
        pigment = "pigment { rgbt <%.9g, %.9g, %.9g, %.9g> }" % (tuple(m["color"]) + (kt,))
        return "%s finish { %s }" % (pigment, " ".join(finish)), m["ior"]
    if kr > 0:
        finish.append("reflection { %.9g }" % kr)
    return "pigment { %s } finish { %s }" % (rgb(m["color"]), " ".join(finish)), None


def read_obj(path):
    positions, faces = [], []
    with open(path) as f:
        for line in f:
            parts = line.split()
            if not parts:
                continue
            if parts[0] == "v":
                positions.append([float(x) for x in parts[1:4]])
            elif parts[0] == "f":
                idx = [int(p.split("/")[0]) for p in parts[1:]]
                idx = [i - 1 if i > 0 else len(positions) + i for i in idx]
                for k in range(1, len(idx) - 1):
                    faces.append((idx[0], idx[k], idx[k + 1]))
    return positions, faces


def normalize(v):
    length = math.sqrt(sum(x * x for x in v))
    return [x / length for x in v] if length > 0 else [0.0, 0.0, 0.0]


def sub(a, b):
    return [a[0] - b[0], a[1] - b[1], a[2] - b[2]]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def mesh_block(path, smooth):
    positions, faces = read_obj(path)
    out = ["mesh2 {", " vertex_vectors { %d, %s }" % (len(positions), ", ".join(v3(p) for p in positions))]
    if smooth:
        normals = [[0.0, 0.0, 0.0] for _ in positions]
        for a, b, c in faces:
            n = normalize(cross(sub(positions[b], positions[a]), sub(positions[c], positions[a])))
            for i in (a, b, c):
                normals[i] = [normals[i][k] + n[k] for k in range(3)]
        out.append(" normal_vectors { %d, %s }" % (len(normals), ", ".join(v3(normalize(n)) for n in normals)))
    out.append(" face_indices { %d, %s }" % (len(faces), ", ".join("<%d, %d, %d>" % f for f in faces)))
    out.append("")
    return "\n".join(out)


def geometry(o, scene_dir):
    """The object's POV-Ray block without its closing brace and the matrix it needs."""
    t = o["type"]
    if t == "sphere":
        g = "sphere { %s, %.9g" % (v3(o["center"]), o["radius"])
    elif t == "plane":
        n = normalize(o["normal"])
        d = sum(n[k] * o["point"][k] for k in range(3))
        return "plane { %s, %.9g" % (v3(n), d)
    elif t == "box":
        g = "box { %s, %s" % (v3(o["min"]), v3(o["max"]))
    elif t == "rectangle":
        c, u, v = o["center"], o["u"], o["v"]
        corner = [[c[k] + su * u[k] + sv * v[k] for k in range(3)] for su, sv in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
        g = "mesh { triangle { %s, %s, %s } triangle { %s, %s, %s }" % (
            v3(corner[0]), v3(corner[1]), v3(corner[2]), v3(corner[0]), v3(corner[2]), v3(corner[3]))
    elif t == "mesh":
        path = o["file"] if os.path.isabs(o["file"]) else os.path.join(scene_dir, o["file"])
        g = mesh_block(path, o.get("smooth_normals", True))
    else:
        raise ValueError("object %r: type %r has no POV-Ray twin" % (o.get("name"), t))
    if not is_identity(o):
        g += " " + pov_matrix(object_matrix(o))
    return g


def convert(doc, scene_dir=".", width=None, height=None):
    """The POV-Ray 3.7 source of scene document `doc` (a parsed scene file) as a string."""
    render = doc.get("render", {})
    width = width or render.get("width", 1280)
    height = height or render.get("height", 720)
    cam = doc.get("camera", {})
    ambient = render.get("ambient", [0.05, 0.05, 0.05])
    shadow_samples = render.get("shadow_samples", 1)
    out = ["// Written by tests/oracle/scene_to_pov.py; the mapping is documented there.",
           "#version 3.7;",
           "global_settings { assumed_gamma 1.0 max_trace_level %d adc_bailout %.9g ambient_light %s }"
           % (render.get("max_depth", 3) + 1, render.get("min_weight", 1.0 / 255.0), rgb(ambient)),
           "background { %s }" % rgb(render.get("background", [0, 0, 0]))]
    position, target = cam.get("position", [0, 0, 0]), cam.get("target", [0, 0, -1])
    up = cam.get("up", [0, 1, 0])
    if cam.get("projection", "perspective") == "orthographic":
        h = cam.get("ortho_height", 2.0)
        lens = "orthographic right x * %.9g up y * %.9g" % (h * width / height, h)
    else:
        fov_x = 2 * math.degrees(math.atan(math.tan(math.radians(cam.get("fov_y", 55.0)) / 2) * width / height))
        lens = "perspective right x * %.9g up y angle %.9g" % (width / height, fov_x)
    out.append("camera { %s location %s look_at %s sky %s }" % (lens, v3(position), v3(target), v3(up)))
    for light in doc.get("lights", []):
        color = [light.get("intensity", 1.0) * c for c in light.get("color", [1, 1, 1])]
        extra = ""
        if shadow_samples > 0 and light.get("type", "point") == "sphere":
            d = 2 * light["radius"]
            s = max(2, int(math.ceil(math.sqrt(shadow_samples))))
            extra = " area_light <%.9g, 0, 0>, <0, 0, %.9g>, %d, %d circular orient" % (d, d, s, s)
        out.append("light_source { %s %s%s }  // %s" % (v3(light["position"]), rgb(color), extra, light.get("name", "")))
    materials = {m["name"]: dict(DEFAULT_MATERIAL, **m) for m in doc.get("materials", [])}
    no_ambient = all(a == 0 for a in ambient)
    for o in doc.get("objects", []):
        if not o.get("visible", True):
            continue
        m = materials.get(o.get("material"), dict(DEFAULT_MATERIAL))
        texture, ior = material_block(m, no_ambient)
        g = geometry(o, scene_dir)
        name = o.get("name", "")
        if shadow_samples == 0:
            texture += " no_shadow"  # not `shadowless` lights: POV-Ray drops their highlights
        if ior is None:
            out.append("%s %s }  // %s" % (g, texture, name))
        else:
            out.append("%s %s interior { ior %.9g } no_shadow }  // %s" % (g, texture, ior, name))
            if shadow_samples > 0:
                out.append("%s pigment { rgb 0 } no_image no_reflection }  // %s: its shadow" % (g, name))
    return "\n".join(out) + "\n"


def main(argv):
    if len(argv) < 3 or argv[1] in ("-h", "--help"):
        print(__doc__)
        return 0 if len(argv) >= 2 and argv[1] in ("-h", "--help") else 2
    options = {"--width": None, "--height": None, "--shadow-samples": None}
    args = argv[3:]
    while args:
        if args[0] in options and len(args) > 1 and args[1].isdigit() and int(args[1]) <= 100000 and \
                (int(args[1]) > 0 or args[0] == "--shadow-samples"):
            options[args[0]] = int(args[1])
            args = args[2:]
        else:
            print("scene_to_pov.py: bad argument %r (expected --width W, --height H or "
                  "--shadow-samples N, integers up to 100000)" % args[0], file=sys.stderr)
            return 2
    width, height = options["--width"], options["--height"]
    try:
        with open(argv[1]) as f:
            doc = json.load(f)
        if options["--shadow-samples"] is not None:
            doc.setdefault("render", {})["shadow_samples"] = options["--shadow-samples"]
        text = convert(doc, os.path.dirname(os.path.abspath(argv[1])), width, height)
    except (OSError, ValueError, KeyError) as e:
        print("scene_to_pov.py: %s: %s" % (argv[1], e), file=sys.stderr)
        return 2
    with open(argv[2], "w") as f:
        f.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
