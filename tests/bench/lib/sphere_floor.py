"""The benchmarks' floor of random spheres (standard library only), shared by
tests/bench/make-bench-scenes.py (the engine scenes and their POV-Ray twins) and
tests/bench/lib/designer-scale.py (the designer at 1k, 10k and 100k spheres)."""
import math

MATERIALS = [
    {"name": "floor", "color": [0.7, 0.7, 0.7], "diffuse": 0.9},
    {"name": "red", "color": [0.8, 0.2, 0.1], "diffuse": 0.9, "specular": 0.4, "shininess": 40},
    {"name": "blue", "color": [0.1, 0.3, 0.8], "diffuse": 0.9, "specular": 0.4, "shininess": 40},
    {"name": "mirror", "color": [0.9, 0.9, 0.9], "diffuse": 0.1, "reflectivity": 0.8},
]
SPHERE_MATERIALS = ("red", "blue", "mirror")


def side_for(n):
    """The floor's side for n spheres: about 16 square units of floor per sphere."""
    return 4.0 * math.sqrt(n)


def sphere_floor(names, rng, side, camera, light, ambient, clear=0.0):
    """A scene: a floor plane and a sphere "ball K" for each K of `names`, scattered over a
    side x side square (radius 0.4 to 1, resting on the floor, material red, blue or mirror
    by K), none centred within `clear` of the origin; one point light at `light`."""
    doc = {
        "format": "raystudio-scene", "version": 1,
        "camera": dict(camera, up=[0, 1, 0], fov_y=55),
        "render": {"width": 1280, "height": 720, "max_depth": 3, "shadow_samples": 1,
                   "background": [0.05, 0.05, 0.08], "ambient": [ambient] * 3},
        "materials": [dict(m) for m in MATERIALS],
        "lights": [{"name": "sun", "type": "point", "position": light}],
        "objects": [{"name": "floor", "type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0],
                     "material": "floor"}],
    }
    for k in names:
        while True:
            x, z = rng.uniform(-side / 2, side / 2), rng.uniform(-side / 2, side / 2)
            if x * x + z * z > clear * clear:
                break
        r = rng.uniform(0.4, 1.0)
        doc["objects"].append({"name": "ball %d" % k, "type": "sphere", "center": [x, r, z],
                               "radius": r, "material": SPHERE_MATERIALS[k % 3]})
    return doc
