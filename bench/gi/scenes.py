#!/usr/bin/env python3
"""The scenes of bench/gi/, described once and written for each renderer.

    python3 bench/gi/scenes.py DIR [--size WxH]

writes DIR/SCENE.crt (crtc), DIR/SCENE.pov (POV-Ray; its radiosity block comes from an
include file, radiosity.inc, that bench/gi/run.sh writes per preset) and DIR/sky.exr's
source DIR/sky.pfm, the panorama (convert it with `oiiotool sky.pfm -d float -o sky.exr`).
bench/gi/cycles.py builds the same scenes in Blender from this module.

Everything is given in the coordinates crtc and POV-Ray share: left-handed, x to the right,
y up, z into the screen. Blender's are right-handed with z up: (x, y, z) here is
(x, z, y) there.

Scenes:
  cornell    the Cornell box as Cornell University publishes it ("Cornell Box data": the
             measured corners in mm, the camera at (278, 273, -800), a 35 mm lens on a
             25 mm film). The data's x axis is right-handed and points to the left as the
             camera sees it; here x is 556 - x, so the red wall is on the left, as in the
             photographs. Every face is two triangles, split at its first corner, because
             the measured faces are not exact parallelograms. The light is lowered 0.1 mm
             below the ceiling (548.7): in the data both lie at 548.8.
  glass      the same box with a glass sphere (ior 1.5) in place of the short block.
  panorama   three diffuse objects on a 100 x 100 ground, lit only by sky.exr: a sky
             gradient and a small sun, made here (sky_texels).
"""
import math
import os
import struct
import sys

# Reflectances (RGB albedo) and the light's radiance, as given with the Cornell box data.
WHITE = (0.725, 0.71, 0.68)
RED = (0.63, 0.065, 0.05)
GREEN = (0.14, 0.45, 0.091)
LIGHT = (17.0, 12.0, 4.0)

# Materials: kind "diffuse" (Lambert, albedo), "emitter" (radiance, both sides, albedo 0),
# "glass" (clear dielectric of the given index, Fresnel reflection and refraction).
MATERIALS = {
    "white": {"kind": "diffuse", "color": WHITE},
    "red": {"kind": "diffuse", "color": RED},
    "green": {"kind": "diffuse", "color": GREEN},
    "light": {"kind": "emitter", "color": LIGHT},
    "glass": {"kind": "glass", "ior": 1.5},
    "ground": {"kind": "diffuse", "color": (0.5, 0.5, 0.5)},
    "clay": {"kind": "diffuse", "color": (0.8, 0.35, 0.2)},
    "chalk": {"kind": "diffuse", "color": (0.8, 0.8, 0.8)},
    "teal": {"kind": "diffuse", "color": (0.1, 0.45, 0.5)},
}

# The Cornell box data (right-handed, mm): each face is its four corners in order.
_LIGHT_Y = 548.7
_CORNELL_FACES = {
    "light": [[(343.0, _LIGHT_Y, 227.0), (343.0, _LIGHT_Y, 332.0), (213.0, _LIGHT_Y, 332.0),
               (213.0, _LIGHT_Y, 227.0)]],
    "white": [
        # floor
        [(552.8, 0.0, 0.0), (0.0, 0.0, 0.0), (0.0, 0.0, 559.2), (549.6, 0.0, 559.2)],
        # ceiling
        [(556.0, 548.8, 0.0), (556.0, 548.8, 559.2), (0.0, 548.8, 559.2), (0.0, 548.8, 0.0)],
        # back wall
        [(549.6, 0.0, 559.2), (0.0, 0.0, 559.2), (0.0, 548.8, 559.2), (556.0, 548.8, 559.2)],
    ],
    "green": [[(0.0, 0.0, 559.2), (0.0, 0.0, 0.0), (0.0, 548.8, 0.0), (0.0, 548.8, 559.2)]],
    "red": [[(552.8, 0.0, 0.0), (549.6, 0.0, 559.2), (556.0, 548.8, 559.2), (556.0, 548.8, 0.0)]],
}
_SHORT_BLOCK = [
    [(130.0, 165.0, 65.0), (82.0, 165.0, 225.0), (240.0, 165.0, 272.0), (290.0, 165.0, 114.0)],
    [(290.0, 0.0, 114.0), (290.0, 165.0, 114.0), (240.0, 165.0, 272.0), (240.0, 0.0, 272.0)],
    [(130.0, 0.0, 65.0), (130.0, 165.0, 65.0), (290.0, 165.0, 114.0), (290.0, 0.0, 114.0)],
    [(82.0, 0.0, 225.0), (82.0, 165.0, 225.0), (130.0, 165.0, 65.0), (130.0, 0.0, 65.0)],
    [(240.0, 0.0, 272.0), (240.0, 165.0, 272.0), (82.0, 165.0, 225.0), (82.0, 0.0, 225.0)],
]
_TALL_BLOCK = [
    [(423.0, 330.0, 247.0), (265.0, 330.0, 296.0), (314.0, 330.0, 456.0), (472.0, 330.0, 406.0)],
    [(423.0, 0.0, 247.0), (423.0, 330.0, 247.0), (472.0, 330.0, 406.0), (472.0, 0.0, 406.0)],
    [(472.0, 0.0, 406.0), (472.0, 330.0, 406.0), (314.0, 330.0, 456.0), (314.0, 0.0, 456.0)],
    [(314.0, 0.0, 456.0), (314.0, 330.0, 456.0), (265.0, 330.0, 296.0), (265.0, 0.0, 296.0)],
    [(265.0, 0.0, 296.0), (265.0, 330.0, 296.0), (423.0, 330.0, 247.0), (423.0, 0.0, 247.0)],
]


def _mirror(p):
    return (round(556.0 - p[0], 6), p[1], p[2])


def _triangles(faces):
    """Each four-corner face as two triangles, split at its first corner, mirrored."""
    tris = []
    for f in faces:
        a, b, c, d = (_mirror(p) for p in f)
        tris += [(a, b, c), (a, c, d)]
    return tris


def _box(lo, hi):
    """The 12 triangles of an axis-aligned box."""
    (x0, y0, z0), (x1, y1, z1) = lo, hi
    p = [(x0, y0, z0), (x1, y0, z0), (x1, y1, z0), (x0, y1, z0),
         (x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)]
    quads = [(0, 1, 2, 3), (5, 4, 7, 6), (4, 0, 3, 7), (1, 5, 6, 2), (3, 2, 6, 7), (4, 5, 1, 0)]
    tris = []
    for a, b, c, d in quads:
        tris += [(p[a], p[b], p[c]), (p[a], p[c], p[d])]
    return tris


# The Cornell camera: 35 mm focal length on a 25 mm square film.
_CORNELL_FOV = 2 * math.degrees(math.atan(12.5 / 35.0))  # 39.3077 degrees


def _cornell(with_short_block):
    meshes = [(m, _triangles(f)) for m, f in _CORNELL_FACES.items()]
    meshes.append(("white", _triangles(_TALL_BLOCK)))
    spheres = []
    if with_short_block:
        meshes.append(("white", _triangles(_SHORT_BLOCK)))
    else:
        # The glass sphere rests on the floor where the short block stood (its centre,
        # (186, 169) in the data, mirrored).
        spheres.append(("glass", (556.0 - 186.0, 90.0, 169.0), 90.0))
    return {
        "camera": {"position": (278.0, 273.0, -800.0), "look_at": (278.0, 273.0, 0.0),
                   "fov": _CORNELL_FOV},
        "meshes": meshes,
        "spheres": spheres,
        "background": {"kind": "color", "color": (0.0, 0.0, 0.0)},
    }


def _panorama():
    return {
        "camera": {"position": (0.0, 1.6, -6.0), "look_at": (0.0, 0.6, 0.0), "fov": 36.0},
        "meshes": [
            ("ground", [((-50.0, 0.0, -50.0), (-50.0, 0.0, 50.0), (50.0, 0.0, 50.0)),
                        ((-50.0, 0.0, -50.0), (50.0, 0.0, 50.0), (50.0, 0.0, -50.0))]),
            ("clay", _box((0.4, 0.0, 0.3), (1.6, 1.2, 1.5))),
        ],
        "spheres": [("chalk", (-0.9, 0.7, 0.2), 0.7), ("teal", (0.3, 0.35, -1.0), 0.35)],
        "background": {"kind": "panorama", "image": "sky.exr"},
    }


SCENES = {"cornell": _cornell(True), "glass": _cornell(False), "panorama": _panorama()}

# The panorama: an equirectangular image, the top row looking up, read by crtc so that its
# centre column is the view along +z and columns to its right turn towards +x
# (docs/rendering.md). The sun stands 40 degrees high, 35 degrees to the right of +z, so
# shadows fall towards the camera and to the left.
SKY_SIZE = (512, 256)
SUN_ELEVATION = 40.0
SUN_AZIMUTH = 35.0  # degrees from +z towards +x
SUN_RADIUS = 2.5  # angular radius, degrees
SUN_RADIANCE = (500.0, 470.0, 420.0)


def sky_direction(u, v):
    """The direction crtc reads at image position (u, v), both in [0, 1], v down."""
    lat = (0.5 - v) * math.pi
    lon = (u - 0.5) * 2 * math.pi  # from +z towards +x
    return (math.cos(lat) * math.sin(lon), math.sin(lat), math.cos(lat) * math.cos(lon))


def sun_direction():
    e, a = math.radians(SUN_ELEVATION), math.radians(SUN_AZIMUTH)
    return (math.cos(e) * math.sin(a), math.sin(e), math.cos(e) * math.cos(a))


def sky_texels():
    """Rows from the top: a blue sky brightening to the horizon, a dark ground below it,
    and the sun, a disc whose texels are weighed by the share of them it covers (4 x 4
    points each)."""
    w, h = SKY_SIZE
    sun = sun_direction()
    cos_r = math.cos(math.radians(SUN_RADIUS))
    rows = []
    for j in range(h):
        row = []
        for i in range(w):
            d = sky_direction((i + 0.5) / w, (j + 0.5) / h)
            y = d[1]
            if y >= 0:
                t = y ** 0.5
                c = [0.9 * (1 - t) + 0.25 * t, 0.95 * (1 - t) + 0.45 * t, 1.1 * (1 - t) + 1.0 * t]
            else:
                t = min(1.0, -y * 8)
                c = [0.9 * (1 - t) + 0.12 * t, 0.95 * (1 - t) + 0.1 * t, 1.1 * (1 - t) + 0.08 * t]
            inside = 0
            for si in range(4):
                for sj in range(4):
                    ds = sky_direction((i + (si + 0.5) / 4) / w, (j + (sj + 0.5) / 4) / h)
                    if ds[0] * sun[0] + ds[1] * sun[1] + ds[2] * sun[2] >= cos_r:
                        inside += 1
            if inside:
                f = inside / 16
                c = [(1 - f) * c[k] + f * SUN_RADIANCE[k] for k in range(3)]
            row.append(c)
        rows.append(row)
    return rows


def write_pfm(path, rows):
    """A float PFM image (its rows stored from the bottom up)."""
    h, w = len(rows), len(rows[0])
    with open(path, "wb") as f:
        f.write(b"PF\n%d %d\n-1.0\n" % (w, h))
        for row in reversed(rows):
            f.write(struct.pack("<%df" % (3 * w), *[x for c in row for x in c]))


# --- crtc ---------------------------------------------------------------------------------

def _v(p):
    return "vec3(%r, %r, %r)" % tuple(float(x) for x in p)


def _rgb(c):
    return "rgb(%r, %r, %r)" % tuple(float(x) for x in c)


def crt_material(m):
    if m["kind"] == "diffuse":
        # diffuse defaults to 1 (no reflectivity or transparency): albedo = color
        return "Material { color -> %s }" % _rgb(m["color"])
    if m["kind"] == "emitter":
        return "Material { color -> rgb(0, 0, 0) emission -> %s }" % _rgb(m["color"])
    # diffuse defaults to 1 - transparency = 0; with fresnel, reflection takes F
    return ("Material { color -> rgb(1, 1, 1) transparency -> 1.0 ior -> %r fresnel -> true }"
            % m["ior"])


def write_crt(path, scene, width, height, samples=64, bounces=8):
    s = SCENES[scene]
    cam = s["camera"]
    bg = s["background"]
    if bg["kind"] == "color":
        background = _rgb(bg["color"])
    else:
        background = 'Background { image -> "%s" }' % bg["image"]
    used = sorted({m for m, _ in s["meshes"]} | {m for m, _, _ in s["spheres"]})
    lines = ["-- bench/gi/ scene %s, written by bench/gi/scenes.py" % scene, ""]
    for m in used:
        lines.append("%s = %s" % (m, crt_material(MATERIALS[m])))
    lines += [
        "",
        "Settings {",
        "    width -> %d height -> %d" % (width, height),
        '    integrator -> "path" samples -> %d bounces -> %d' % (samples, bounces),
        "    camera -> Camera { position -> %s pointing -> %s fov -> %r }"
        % (_v(cam["position"]), _v(cam["look_at"]), cam["fov"]),
        "    background -> %s" % background,
        "}",
        "",
        "Scene {",
    ]
    for m, tris in s["meshes"]:
        for a, b, c in tris:
            lines.append("    Triangle { a -> %s b -> %s c -> %s material -> %s }" % (_v(a), _v(b), _v(c), m))
    for m, c, r in s["spheres"]:
        lines.append("    Sphere { center -> %s radius -> %r material -> %s }" % (_v(c), r, m))
    lines.append("}")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


# --- POV-Ray ------------------------------------------------------------------------------

# POV-Ray's spherical map (map_type 1) reads the image's u from +x towards +z (u = 0.25 at
# +z), the mirror image of crtc's mapping turned a quarter: the sky is seen through the
# reflection (x, y, z) -> (-z, y, -x), its own inverse. Checked by rendering the sky alone
# in the three renderers, looking 20 degrees beside the sun (bench/README.md).
POV_SKY_MATRIX = "matrix <0, 0, -1, 0, 1, 0, -1, 0, 0, 0, 0, 0>"


def _pv(p):
    return "<%r, %r, %r>" % tuple(float(x) for x in p)


def pov_texture(m):
    if m["kind"] == "diffuse":
        return "texture { pigment { rgb %s } finish { ambient 0 emission 0 diffuse 1 } }" % _pv(m["color"])
    if m["kind"] == "emitter":
        return "texture { pigment { rgb %s } finish { ambient 0 emission 1 diffuse 0 } }" % _pv(m["color"])
    return ("texture { pigment { rgbt <1, 1, 1, 1> } finish { ambient 0 emission 0 diffuse 0"
            " reflection { 0, 1 fresnel on } conserve_energy } }")


def pov_interior(m):
    return " interior { ior %r }" % m["ior"] if m["kind"] == "glass" else ""


def write_pov(path, scene, width, height):
    s = SCENES[scene]
    cam = s["camera"]
    # POV-Ray's angle is the horizontal one; crtc's fov the vertical one.
    hfov = 2 * math.degrees(math.atan(math.tan(math.radians(cam["fov"]) / 2) * width / height))
    bg = s["background"]
    lines = [
        "// bench/gi/ scene %s, written by bench/gi/scenes.py" % scene,
        "#version 3.7;",
        "global_settings {",
        "    assumed_gamma 1.0",
        "    ambient_light 0",
        "    max_trace_level 16",
        "    adc_bailout 0",
        '    #include "radiosity.inc"',
        "}",
        "camera { perspective location %s look_at %s right x * %r up y angle %r }"
        % (_pv(cam["position"]), _pv(cam["look_at"]), width / height, hfov),
    ]
    if bg["kind"] == "color":
        lines.append("background { rgb %s }" % _pv(bg["color"]))
    else:
        lines.append('sky_sphere { pigment { image_map { exr "%s" map_type 1 interpolate 2 } %s } }'
                     % (bg["image"], POV_SKY_MATRIX))
    for m, tris in s["meshes"]:
        lines.append("mesh {")
        for a, b, c in tris:
            lines.append("    triangle { %s, %s, %s }" % (_pv(a), _pv(b), _pv(c)))
        lines.append("    %s%s" % (pov_texture(MATERIALS[m]), pov_interior(MATERIALS[m])))
        lines.append("}")
    for m, c, r in s["spheres"]:
        lines.append("sphere { %s, %r %s%s }" % (_pv(c), r, pov_texture(MATERIALS[m]), pov_interior(MATERIALS[m])))
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def main(argv):
    if len(argv) < 2 or argv[1] in ("-h", "--help"):
        print(__doc__.strip())
        return 0 if len(argv) >= 2 else 2
    out = argv[1]
    width, height = 256, 256
    if len(argv) >= 4 and argv[2] == "--size":
        width, height = (int(x) for x in argv[3].split("x"))
    os.makedirs(out, exist_ok=True)
    for name in SCENES:
        write_crt(os.path.join(out, name + ".crt"), name, width, height)
        write_pov(os.path.join(out, name + ".pov"), name, width, height)
    write_pfm(os.path.join(out, "sky.pfm"), sky_texels())
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
