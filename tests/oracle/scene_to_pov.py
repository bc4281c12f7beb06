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
- Shadows: ours multiply a shadow ray by transparency * colour at each surface it crosses
  (no bending, no caustics); POV-Ray's `filter` f passes f * colour at each crossing, but its
  transmitting camera-ray pigment must stay `transmit` (the refraction above). So a glass
  object gets `no_shadow` and a shadow-only twin (`no_image no_reflection`, which refracted
  rays do not see either) with `rgbf <color, transparency>` casts its shadow; with
  render.opaque_shadows the twin is black, version 1's opaque shadow.
- Checker (`color: {checker, scale}`): POV-Ray's `checker` with `scale s`, evaluated at the
  point of ours (the pattern's z flipped back), declared before the object's transform so it
  moves with the object.
- Image textures (`color: {texture, scale, offset}`): an `image_map` (8-bit files
  `gamma srgb`, float files linear, `interpolate 2`, repeating) at uv' = uv * scale + offset:
  spheres and rectangles through `uv_mapping` (a rectangle is a mesh2 with uv_vectors; POV-Ray's
  sphere u runs the other way round in its flipped frame, u = 1 - u_pov), planes a planar map
  whose pattern x, y are u = (p - point).T1, v = (p - point).T2. Boxes and meshes have no twin.
- Environment: `sky_sphere` with a spherical (`map_type 1`) image_map of the file, turned by
  `rotate y * rotation` (the same matrix as our rotation about +Y) and evaluated at the
  direction of ours (z flipped back); `emission` scales it by intensity. It replaces
  `background` for every ray that escapes, as ours.
- Directional light: `parallel` from far along -direction, `point_at` the origin. Spot light:
  `spotlight` with radius and falloff (half-angles) and `tightness 0`.
- Depth: our max_depth counts bounces, POV-Ray's max_trace_level counts the camera ray too:
  level = max_depth + 1. Both return black past it. adc_bailout is our min_weight.
- Geometry: sphere, plane, box, rectangle (a two-triangle mesh2 with UVs), mesh (mesh2 from the OBJ file with
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


def affine_inverse(m):
    """The inverse of a 3x4 affine map (rows, column vectors) as a 3x4 map."""
    a = [row[:3] for row in m]
    det = (a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0])
           + a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]))
    inv = [[(a[(j + 1) % 3][(i + 1) % 3] * a[(j + 2) % 3][(i + 2) % 3]
             - a[(j + 1) % 3][(i + 2) % 3] * a[(j + 2) % 3][(i + 1) % 3]) / det for j in range(3)] for i in range(3)]
    t = [-sum(inv[i][k] * m[k][3] for k in range(3)) for i in range(3)]
    return [inv[i] + [t[i]] for i in range(3)]


def raw_matrix(m):
    """A 3x4 affine map (rows, column vectors) in POV-Ray's row-vector `matrix` order, unflipped."""
    cols = [m[0][0], m[1][0], m[2][0], m[0][1], m[1][1], m[2][1], m[0][2], m[1][2], m[2][2],
            m[0][3], m[1][3], m[2][3]]
    return "matrix <%s>" % ", ".join("%.9g" % x for x in cols)


# F = diag(1, 1, -1): a point of ours in POV-Ray's frame and back.
FLIP = [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, -1, 0]]


def image_map(path, scene_dir):
    """An image_map block (planar, repeating) of texture file `path`; 8-bit files are sRGB."""
    full = path if os.path.isabs(path) else os.path.join(scene_dir, path)
    ext = os.path.splitext(full)[1].lower().lstrip(".")
    kind = {"png": "png", "jpg": "jpeg", "jpeg": "jpeg", "tif": "tiff", "tiff": "tiff", "hdr": "hdr",
            "exr": "exr"}.get(ext)
    if kind is None:
        raise ValueError("texture %r: POV-Ray reads no %r files" % (path, ext))
    gamma = "" if kind in ("hdr", "exr") else " gamma srgb"
    return 'image_map { %s "%s"%s interpolate 2 }' % (kind, full.replace("\\", "/"), gamma)


def pigment(m, o, scene_dir):
    """The pigment of material `m` on object `o` (in the object's POV-Ray frame, before its
    transform): flat colour, solid checker, or an image through the shape's UVs."""
    c = m["color"]
    kt = m["transparency"]
    if isinstance(c, list):
        return "pigment { rgbt <%.9g, %.9g, %.9g, %.9g> }" % (tuple(c) + (kt,)) if kt > 0 else "pigment { %s }" % rgb(c)
    if "checker" in c:
        a, b = c["checker"]
        s = c.get("scale", 1.0)
        fmt = "rgbt <%.9g, %.9g, %.9g, %.9g>" % (tuple(a) + (kt,)), "rgbt <%.9g, %.9g, %.9g, %.9g>" % (tuple(b) + (kt,))
        # The pattern is evaluated at the point of ours (z flipped back), cells of side s.
        return "pigment { checker color %s color %s scale %.9g %s }" % (fmt[0], fmt[1], s, raw_matrix(FLIP))
    if "texture" not in c:
        raise ValueError("material %r: color %r has no POV-Ray twin" % (m.get("name"), c))
    su, sv = c.get("scale", [1.0, 1.0])
    ou, ov = c.get("offset", [0.0, 0.0])
    t = o["type"]
    if t == "plane":
        # u = (p - point).T1, v = (p - point).T2 of the point p of ours = F P.
        n = normalize(o["normal"])
        axis = [0.0, 0.0, 1.0] if abs(n[0]) > 0.9 else [1.0, 0.0, 0.0]
        d = sum(n[k] * axis[k] for k in range(3))
        t1 = normalize([axis[k] - n[k] * d for k in range(3)])
        t2 = cross(n, t1)
        q = o["point"]
        rows = []
        for axis_row, s_, o_ in ((t1, su, ou), (t2, sv, ov), (n, 1.0, 0.0)):
            r = [axis_row[0] * s_, axis_row[1] * s_, -axis_row[2] * s_]
            rows.append(r + [o_ - s_ * sum(axis_row[k] * q[k] for k in range(3))])
        where = raw_matrix(affine_inverse(rows))
        mapping = ""
    else:
        # uv_mapping: the pattern point is (u, v, 0) of the shape's UVs. POV-Ray's sphere
        # measures u in its own (flipped) frame: u_ours = 1 - u_pov.
        flip_u = t == "sphere"
        rows = [[-su if flip_u else su, 0, 0, ou + (su if flip_u else 0.0)], [0, sv, 0, ov], [0, 0, 1, 0]]
        where = raw_matrix(affine_inverse(rows))
        mapping = "uv_mapping "
    block = image_map(c["texture"], scene_dir)
    if kt > 0:
        block = block[:-2] + " transmit all %.9g }" % kt
    return "pigment { %s%s %s }" % (mapping, block, where)


def material_block(m, scene_ambient_is_zero, pig):
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
        return "%s finish { %s }" % (pig, " ".join(finish)), m["ior"]
    if kr > 0:
        finish.append("reflection { %.9g }" % kr)
    return "%s finish { %s }" % (pig, " ".join(finish)), None


def shadow_pigment(m):
    """What a glass object's shadow-only twin lets through: ours multiplies a shadow ray by
    transparency * colour at each crossing, POV-Ray's `filter` f passes f * colour (a pattern's
    colour at the crossing point, as ours)."""
    c, kt = m["color"], m["transparency"]
    if isinstance(c, list):
        return "pigment { rgbf <%.9g, %.9g, %.9g, %.9g> }" % (tuple(c) + (kt,))
    return None


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
    """The object's POV-Ray block without its closing brace, and its transform ('' if none):
    textures go between the two, so that they move with the object."""
    t = o["type"]
    if t == "sphere":
        g = "sphere { %s, %.9g" % (v3(o["center"]), o["radius"])
    elif t == "plane":
        n = normalize(o["normal"])
        d = sum(n[k] * o["point"][k] for k in range(3))
        return "plane { %s, %.9g" % (v3(n), d), ""
    elif t == "box":
        g = "box { %s, %s" % (v3(o["min"]), v3(o["max"]))
    elif t == "rectangle":
        c, u, v = o["center"], o["u"], o["v"]
        corner = [[c[k] + su * u[k] + sv * v[k] for k in range(3)] for su, sv in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
        # u = (a + 1) / 2, v = (b + 1) / 2 for the point c + a u + b v.
        g = ("mesh2 { vertex_vectors { 4, %s, %s, %s, %s } uv_vectors { 4, <0, 0>, <1, 0>, <1, 1>, <0, 1> }"
             " face_indices { 2, <0, 1, 2>, <0, 2, 3> } uv_indices { 2, <0, 1, 2>, <0, 2, 3> }"
             % (v3(corner[0]), v3(corner[1]), v3(corner[2]), v3(corner[3])))
    elif t == "mesh":
        path = o["file"] if os.path.isabs(o["file"]) else os.path.join(scene_dir, o["file"])
        g = mesh_block(path, o.get("smooth_normals", True))
    else:
        raise ValueError("object %r: type %r has no POV-Ray twin" % (o.get("name"), t))
    return g, ("" if is_identity(o) else pov_matrix(object_matrix(o)))


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
    env = doc.get("environment")
    if env is not None:
        # POV-Ray's spherical map measures u in its flipped frame: the map is evaluated at the
        # direction of ours (z flipped back) turned by `rotation` about +Y (POV-Ray's `rotate y`
        # is the same matrix as our right-handed rotation about +Y).
        intensity = env.get("intensity", 1.0)
        out.append("sky_sphere { pigment { %s map_type 1 } rotate y * %.9g %s } emission rgb %.9g }"
                   % (image_map(env["file"], scene_dir)[:-2], env.get("rotation", 0.0),
                      raw_matrix(FLIP), intensity))
    for light in doc.get("lights", []):
        color = [light.get("intensity", 1.0) * c for c in light.get("color", [1, 1, 1])]
        kind = light.get("type", "point")
        extra = ""
        if kind == "directional":
            # A parallel light from far up its direction; only the direction matters to POV-Ray.
            d = normalize(light["direction"])
            far = [-1e4 * d[k] for k in range(3)]
            out.append("light_source { %s %s parallel point_at <0, 0, 0> }  // %s"
                       % (v3(far), rgb(color), light.get("name", "")))
            continue
        if kind == "spot":
            extra = " spotlight point_at %s radius %.9g falloff %.9g tightness 0" % (
                v3(light["target"]), light["radius"], light["falloff"])
        if shadow_samples > 0 and kind == "sphere":
            d = 2 * light["radius"]
            s = max(2, int(math.ceil(math.sqrt(shadow_samples))))
            extra = " area_light <%.9g, 0, 0>, <0, 0, %.9g>, %d, %d circular orient" % (d, d, s, s)
        out.append("light_source { %s %s%s }  // %s" % (v3(light["position"]), rgb(color), extra, light.get("name", "")))
    materials = {m["name"]: dict(DEFAULT_MATERIAL, **m) for m in doc.get("materials", [])}
    no_ambient = all(a == 0 for a in ambient)
    opaque_shadows = render.get("opaque_shadows", False)
    for o in doc.get("objects", []):
        if not o.get("visible", True):
            continue
        m = materials.get(o.get("material"), dict(DEFAULT_MATERIAL))
        texture, ior = material_block(m, no_ambient, pigment(m, o, scene_dir))
        g, where = geometry(o, scene_dir)
        name = o.get("name", "")
        if shadow_samples == 0:
            texture += " no_shadow"  # not `shadowless` lights: POV-Ray drops their highlights
        if ior is None:
            out.append("%s %s %s }  // %s" % (g, texture, where, name))
        else:
            out.append("%s %s interior { ior %.9g } %s no_shadow }  // %s" % (g, texture, ior, where, name))
            if shadow_samples > 0:
                shadow = None if opaque_shadows else shadow_pigment(m)
                if shadow is None and not opaque_shadows:
                    raise ValueError("object %r: a patterned glass's filtered shadow has no twin" % name)
                out.append("%s %s %s no_image no_reflection }  // %s: its shadow"
                           % (g, shadow or "pigment { rgb 0 }", where, name))
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
