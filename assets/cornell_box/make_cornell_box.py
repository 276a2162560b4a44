#!/usr/bin/env python3
"""Write voxatlas's own test scenes as self-contained glTF 2.0 files.

Variants (see README.md beside this script for the source of every number):

  cornell (default)  The Cornell box from the Cornell University Program of
                     Computer Graphics "Cornell Box Data" page, converted to
                     glTF units and axes, lit by one KHR_lights_punctual point
                     light under the ceiling.  Default output:
                     cornell_box.gltf beside this script.
  animated           The Cornell box with a blue cube sliding and turning along the
                     front of the floor (glTF animations, 4 s loop): the demo of
                     dynamic GI.  Default output: cornell_box_animated.gltf.
  plane              A 2 m x 2 m grey floor under a point light, for the
                     analytic radiance test.  Default output:
                     ../analytic/plane_point_light.gltf relative to this script.

Usage:  make_cornell_box.py [--variant cornell|plane] [--out PATH]

The output is deterministic: the same bytes on every run.
"""

import argparse
import math
import os
import sys

sys.dont_write_bytecode = True  # no module cache left beside the assets
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))

from gltf_builder import GltfWriter, MeshBuilder, mean, sub, write_atomically  # noqa: E402

GENERATOR = "voxatlas make_cornell_box.py"

# --------------------------------------------------------------------------
# Cornell box data, millimetres, exactly as published (Cornell Box Data page).
# The data's frame: +Y up, camera at z = -800 looking toward +z.  Read as a
# right-handed frame (the only reading that puts the red wall on the left of
# the published photographs), the camera's right is -x: the red wall at
# x ~ 556 is on the left, the green wall at x = 0 on the right.
# Every face is a quad; vertex order here is the published order, and the
# winding is fixed later from geometry, not trusted from the listing.
# --------------------------------------------------------------------------
CORNELL_FLOOR = [(552.8, 0.0, 0.0), (0.0, 0.0, 0.0), (0.0, 0.0, 559.2), (549.6, 0.0, 559.2)]
CORNELL_CEILING = [(556.0, 548.8, 0.0), (556.0, 548.8, 559.2), (0.0, 548.8, 559.2), (0.0, 548.8, 0.0)]
CORNELL_BACK_WALL = [(549.6, 0.0, 559.2), (0.0, 0.0, 559.2), (0.0, 548.8, 559.2), (556.0, 548.8, 559.2)]
CORNELL_RIGHT_WALL_GREEN = [(0.0, 0.0, 559.2), (0.0, 0.0, 0.0), (0.0, 548.8, 0.0), (0.0, 548.8, 559.2)]
CORNELL_LEFT_WALL_RED = [(552.8, 0.0, 0.0), (549.6, 0.0, 559.2), (556.0, 548.8, 559.2), (556.0, 548.8, 0.0)]
# The light opening in the ceiling (used only to place the point light).
CORNELL_LIGHT = [(343.0, 548.8, 227.0), (343.0, 548.8, 332.0), (213.0, 548.8, 332.0), (213.0, 548.8, 227.0)]

CORNELL_SHORT_BLOCK = [
    [(130.0, 165.0, 65.0), (82.0, 165.0, 225.0), (240.0, 165.0, 272.0), (290.0, 165.0, 114.0)],
    [(290.0, 0.0, 114.0), (290.0, 165.0, 114.0), (240.0, 165.0, 272.0), (240.0, 0.0, 272.0)],
    [(130.0, 0.0, 65.0), (130.0, 165.0, 65.0), (290.0, 165.0, 114.0), (290.0, 0.0, 114.0)],
    [(82.0, 0.0, 225.0), (82.0, 165.0, 225.0), (130.0, 165.0, 65.0), (130.0, 0.0, 65.0)],
    [(240.0, 0.0, 272.0), (240.0, 165.0, 272.0), (82.0, 165.0, 225.0), (82.0, 0.0, 225.0)],
]
CORNELL_TALL_BLOCK = [
    [(423.0, 330.0, 247.0), (265.0, 330.0, 296.0), (314.0, 330.0, 456.0), (472.0, 330.0, 406.0)],
    [(423.0, 0.0, 247.0), (423.0, 330.0, 247.0), (472.0, 330.0, 406.0), (472.0, 0.0, 406.0)],
    [(472.0, 0.0, 406.0), (472.0, 330.0, 406.0), (314.0, 330.0, 456.0), (314.0, 0.0, 456.0)],
    [(314.0, 0.0, 456.0), (314.0, 330.0, 456.0), (265.0, 330.0, 296.0), (265.0, 0.0, 296.0)],
    [(265.0, 0.0, 296.0), (265.0, 330.0, 296.0), (423.0, 330.0, 247.0), (423.0, 0.0, 247.0)],
]

CORNELL_CAMERA_MM = (278.0, 273.0, -800.0)   # looks along +z, up +y
CORNELL_FOCAL_LENGTH_M = 0.035
CORNELL_FILM_HEIGHT_M = 0.025
CORNELL_CEILING_Y_MM = 548.8
CORNELL_BOX_WIDTH_MM = 556.0                 # widest x extent (ceiling)

# Linear-RGB albedos derived from the published reflectance spectra, as used
# by the widely shared PBRT/Mitsuba Cornell box scenes.
CORNELL_MATERIALS = [
    ("white", (0.725, 0.71, 0.68)),
    ("red", (0.63, 0.065, 0.05)),
    ("green", (0.14, 0.45, 0.091)),
]

# Point light: 1 cm below the ceiling at the centre of the light opening.
# Radiant intensity 0.3 W/sr gives E = 0.3 / 0.5388^2 ~ 1.03 W/m^2 on the floor
# directly below it.
CORNELL_LIGHT_DROP_MM = 10.0
CORNELL_LIGHT_INTENSITY = 0.3


def cornell_to_gltf(p, scale=1.0):
    """Cornell millimetres -> glTF metres (times `scale`).

    Mirroring z alone would give the camera its glTF -Z view direction but
    would also reflect the scene (red wall on the right).  Mirroring x as well
    turns the change into a rotation by 180 degrees about the vertical line
    x = 278 mm, z = 0, which keeps handedness, windings and the photographed
    left/right layout.  x is mirrored about the box's widest extent (556 mm)
    so that every x stays in [0, 0.556] and the camera stays at x = 0.278.
    """
    x, y, z = p
    # "+ 0.0" turns -0.0 (from z = 0) into 0.0 so the file never shows "-0.0".
    return ((CORNELL_BOX_WIDTH_MM - x) / 1000.0 * scale, y / 1000.0 * scale,
            -z / 1000.0 * scale + 0.0)


# --------------------------------------------------------------------------
# Scenes.
# --------------------------------------------------------------------------
def add_cornell_materials(w, double_sided=False):
    for name, rgb in CORNELL_MATERIALS:
        w.add_material(name, rgb, double_sided)


def add_cornell_geometry(w, scale=1.0, texcoords=False, block_materials=("white", "white")):
    """The five room quads and the two blocks (short, tall: `block_materials`), one mesh node
    each."""
    def conv(quad):
        return [cornell_to_gltf(p, scale) for p in quad]

    # Room surfaces face the inside of the box: towards the centre of its
    # bounding box.
    room_centre = cornell_to_gltf(
        (CORNELL_BOX_WIDTH_MM / 2.0, CORNELL_CEILING_Y_MM / 2.0, 559.2 / 2.0), scale)
    room = [
        ("floor", CORNELL_FLOOR, "white"),
        ("ceiling", CORNELL_CEILING, "white"),
        ("back_wall", CORNELL_BACK_WALL, "white"),
        ("left_wall_red", CORNELL_LEFT_WALL_RED, "red"),
        ("right_wall_green", CORNELL_RIGHT_WALL_GREEN, "green"),
    ]
    for name, quad, material in room:
        q = conv(quad)
        m = MeshBuilder()
        m.add_quad(q, sub(room_centre, mean(q)))
        w.add_mesh_node(name, m, material, texcoords)

    # Block faces face away from the block's centre.  No bottom faces: they
    # rest on the floor and are never seen.
    blocks = (("short_block", CORNELL_SHORT_BLOCK), ("tall_block", CORNELL_TALL_BLOCK))
    for (name, faces), material in zip(blocks, block_materials):
        quads = [conv(f) for f in faces]
        centre = mean([p for q in quads for p in q])
        m = MeshBuilder()
        for q in quads:
            m.add_quad(q, sub(mean(q), centre))
        w.add_mesh_node(name, m, material, texcoords)


def cornell_light_position(scale=1.0, drop_mm=CORNELL_LIGHT_DROP_MM):
    """Centre of the light opening, `drop_mm` (Cornell millimetres) under the ceiling."""
    lx, _, lz = cornell_to_gltf(mean(CORNELL_LIGHT), scale)
    return (round(lx, 6), round((CORNELL_CEILING_Y_MM - drop_mm) / 1000.0 * scale, 6), round(lz, 6))


def add_cornell_camera(w, scale=1.0):
    # Published camera: 35 mm lens, 25 mm film -> yfov = 2 atan(12.5 / 35).
    # After the conversion it looks down -Z with +Y up, glTF's default
    # camera orientation, so the node needs no rotation.
    cam_pos = tuple(round(c, 6) for c in cornell_to_gltf(CORNELL_CAMERA_MM, scale))
    yfov = 2.0 * math.atan(0.5 * CORNELL_FILM_HEIGHT_M / CORNELL_FOCAL_LENGTH_M)
    w.add_camera_node("camera", cam_pos, yfov, 0.01 * scale, 10.0 * scale)


def build_cornell(generator=GENERATOR):
    w = GltfWriter(generator)
    add_cornell_materials(w)
    add_cornell_geometry(w)
    w.add_point_light_node("ceiling_light", cornell_light_position(), (1.0, 1.0, 1.0),
                           CORNELL_LIGHT_INTENSITY)
    add_cornell_camera(w)
    return w, "cornell_box"


# The same box lit only by an emissive panel filling the light opening, 1 mm under the
# ceiling and facing down, with the radiance that gives the point light's intensity on its
# axis: I = L x A, A = 0.130 m x 0.105 m, L = 0.3 / A = 21.98 W/(m^2 sr).
CORNELL_PANEL_DROP_MM = 1.0
CORNELL_PANEL_RADIANCE = round(CORNELL_LIGHT_INTENSITY / (0.130 * 0.105), 4)


def build_cornell_emissive(generator=GENERATOR):
    w = GltfWriter(generator)
    add_cornell_materials(w)
    w.add_material("light_panel", (0.0, 0.0, 0.0), emissive=(1.0, 1.0, 1.0),
                   emissive_strength=CORNELL_PANEL_RADIANCE)
    add_cornell_geometry(w)
    y = CORNELL_CEILING_Y_MM - CORNELL_PANEL_DROP_MM
    panel = [cornell_to_gltf((x, y, z)) for x, _, z in CORNELL_LIGHT]
    m = MeshBuilder()
    m.add_quad(panel, (0.0, -1.0, 0.0))
    w.add_mesh_node("light_panel", m, "light_panel")
    add_cornell_camera(w)
    return w, "cornell_box_emissive"


# Analytic test scene: radiance of the floor is rho/pi * I cos(theta) / d^2.
PLANE_HALF_SIZE = 1.0
PLANE_ALBEDO = 0.5
PLANE_LIGHT_POS = (0.0, 1.0, 0.0)
PLANE_LIGHT_INTENSITY = 1.0
PLANE_CAMERA_POS = (0.0, 1.0, 2.2)
PLANE_CAMERA_YFOV_DEG = 45.0


def build_plane():
    w = GltfWriter(GENERATOR)
    w.add_material("white", (PLANE_ALBEDO, PLANE_ALBEDO, PLANE_ALBEDO))
    s = PLANE_HALF_SIZE
    m = MeshBuilder()
    m.add_quad([(-s, 0.0, -s), (-s, 0.0, s), (s, 0.0, s), (s, 0.0, -s)], (0.0, 1.0, 0.0))
    w.add_mesh_node("floor", m, "white")
    w.add_point_light_node("point_light", PLANE_LIGHT_POS, (1.0, 1.0, 1.0), PLANE_LIGHT_INTENSITY)

    # Aim the camera's -Z at the origin.  The target lies straight ahead in
    # the y-z plane, so a rotation about +X by a negative angle (pitch down)
    # suffices: R_x(a) maps -Z to (0, sin a, -cos a).
    _, cy, cz = PLANE_CAMERA_POS
    pitch = -math.atan2(cy, cz)
    rotation = (math.sin(pitch / 2.0), 0.0, 0.0, math.cos(pitch / 2.0))
    w.add_camera_node("camera", PLANE_CAMERA_POS, math.radians(PLANE_CAMERA_YFOV_DEG), 0.01, 10.0, rotation)
    return w, "plane_point_light"


# The animated demo: a blue cube slides along the front of the floor, from beside the red
# wall (x = 0 in glTF) to beside the green one and back, turning as it goes, so its bounce light (blue on the
# floor, red or green on its sides) moves with it. Only the cube is dynamic.
ANIMATED_CUBE_HALF = 0.04
ANIMATED_CUBE_ALBEDO = (0.1, 0.2, 0.8)
ANIMATED_CUBE_PATH = ((0.10, 0.04, -0.05), (0.50, 0.04, -0.05))  # ends of the slide (m)
ANIMATED_PERIOD_S = 4.0


def build_animated():
    w, _ = build_cornell()
    w.add_material("blue", ANIMATED_CUBE_ALBEDO)
    h = ANIMATED_CUBE_HALF
    m = MeshBuilder()
    corners = [(x, y, z) for x in (-h, h) for y in (-h, h) for z in (-h, h)]
    for axis in range(3):
        for side in (-h, h):
            face = [c for c in corners if c[axis] == side]
            # Order the four corners around the face before add_quad orients them.
            u, v = [i for i in range(3) if i != axis]
            face.sort(key=lambda c: math.atan2(c[v], c[u]))
            facing = tuple(side if i == axis else 0.0 for i in range(3))
            m.add_quad(face, facing)
    cube = w.add_mesh_node("animated_cube", m, "blue")
    start, end = ANIMATED_CUBE_PATH
    w.doc["nodes"][cube]["translation"] = list(start)
    half = ANIMATED_PERIOD_S / 2.0
    w.add_animation("slide", cube, "translation", [0.0, half, ANIMATED_PERIOD_S], [start, end, start])
    turn = math.radians(90.0) / 2.0
    w.add_animation("turn", cube, "rotation", [0.0, half, ANIMATED_PERIOD_S],
                    [(0.0, 0.0, 0.0, 1.0), (0.0, math.sin(turn), 0.0, math.cos(turn)), (0.0, 0.0, 0.0, 1.0)])
    return w, "cornell_box_animated"


VARIANTS = {
    "cornell": (build_cornell, ("cornell_box.gltf",)),
    "animated": (build_animated, ("cornell_box_animated.gltf",)),
    "emissive": (build_cornell_emissive, ("cornell_box_emissive.gltf",)),
    "plane": (build_plane, ("..", "analytic", "plane_point_light.gltf")),
}


def main(argv=None):
    parser = argparse.ArgumentParser(description="Write the voxatlas test scenes as glTF 2.0 files.")
    parser.add_argument("--variant", choices=sorted(VARIANTS), default="cornell",
                        help="scene to write (default: cornell)")
    parser.add_argument("--out", help="output path (default: cornell_box.gltf beside this script, "
                                      "or ../analytic/plane_point_light.gltf for --variant plane)")
    args = parser.parse_args(argv)

    build, default_rel = VARIANTS[args.variant]
    out = args.out or os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), *default_rel))
    writer, scene_name = build()
    data = writer.finish(scene_name)

    write_atomically(out, data)
    print(writer.summary(out, data))
    return 0


if __name__ == "__main__":
    sys.exit(main())
