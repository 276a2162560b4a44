#!/usr/bin/env python3
"""Write the accuracy scene suite: small glTF 2.0 scenes, each testing one thing.

Every file carries its own cameras and KHR_lights_punctual lights, in the units of
docs/conventions.md (metres; W/sr for point and spot lights, W/m^2 for directional ones;
Lambertian materials but one).  README.md beside this script says what each scene tests.

  cornell_classic         the Cornell box of ../cornell_box (same geometry, camera, light)
  cornell_double_sided    the same, every material doubleSided and TEXCOORD_0 on every
                          primitive (what Blender and most exporters write)
  cornell_glossy          the same with the tall block a grey metal (metallic 1, roughness 0.3)
  cornell_low_light       the point light 10 % of the box height under the ceiling
  cornell_x10             the whole box x10; the light x100, so the radiance stays the same
  cornell_spot            one spot light pointing down from under the ceiling
  cornell_open_front_sun  the box on a ground, lit by a sun through its open front
  two_rooms_thin_wall     two closed rooms sharing one wall one finest voxel thick, a point
                          light in one of them: light in the other one is a leak
  closed_white_box        a closed white box, a point light at its centre: energy balance

The shared wall of two_rooms_thin_wall is as thick as one finest voxel of the adaptive
resource plan (render.plan=adaptive, src/render/ResourcePlan.cpp) at the default
voxel.resolution = 32 and voxel.size = 0: 2.2 x the scene's longest side / 2^(levels - 1) / 32,
levels = 1 + ceil(log2(2.2 x longest / shortest)).  The rooms are laid out so that neither
side depends on the wall: each room is 2 m wide (x) side by side, 4.5 m deep (z), 2.5 m high
(y), so longest = 4.5 m, shortest = 2.5 m, levels = 3 and the wall is 9.9 / 4 / 32 =
0.07734375 m thick (`voxatlas info two_rooms_thin_wall.gltf --set render.plan=adaptive`
prints it as the finest voxel).  The fixed plan (render.plan=fixed, the default) sizes its
cascade from the camera instead, so its finest voxel changes with the view.

Both rooms are closed by single-sided quads facing inward (floor, ceiling, outer wall, front
and back walls), and the shared wall is a closed slab (six outward faces) filling the gap
between the rooms: a ray leaving the lit room meets a surface facing it, so light reaches the
dark room only by passing through the slab's thickness.

Usage:  make_scene_suite.py            (re)write every scene beside this script
        make_scene_suite.py --check    exit 1 if a committed scene differs from this script's

The output is deterministic: the same bytes on every run.
"""

import math
import os
import sys

sys.dont_write_bytecode = True  # no module cache left beside the assets
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "common"))
sys.path.insert(0, os.path.join(HERE, "..", "cornell_box"))

from gltf_builder import (GltfWriter, MeshBuilder, f32, look_rotation, sub,  # noqa: E402
                          write_atomically)
import make_cornell_box as cornell  # noqa: E402

GENERATOR = "voxatlas make_scene_suite.py"
WHITE = (1.0, 1.0, 1.0)

# The box's inner height (m), from the floor to the ceiling.
CORNELL_HEIGHT_M = cornell.CORNELL_CEILING_Y_MM / 1000.0


def cornell_scene(light, scale=1.0, double_sided=False, texcoords=False):
    """The Cornell box's geometry and camera around the light `light(writer)` adds."""
    w = GltfWriter(GENERATOR)
    cornell.add_cornell_materials(w, double_sided)
    cornell.add_cornell_geometry(w, scale, texcoords)
    light(w)
    cornell.add_cornell_camera(w, scale)
    return w


def classic_point_light(w, scale=1.0, drop_mm=cornell.CORNELL_LIGHT_DROP_MM):
    w.add_point_light_node("ceiling_light", cornell.cornell_light_position(scale, drop_mm), WHITE,
                           round(cornell.CORNELL_LIGHT_INTENSITY * scale * scale, 9))


def build_classic():
    return cornell_scene(classic_point_light)


# The tall block a rough grey metal: the glossy model's test (scripts/measure_glossy.py).
GLOSSY_METAL_RGB = (0.8, 0.8, 0.8)
GLOSSY_METAL_ROUGHNESS = 0.3


def build_glossy():
    w = GltfWriter(GENERATOR)
    cornell.add_cornell_materials(w)
    w.add_material("metal", GLOSSY_METAL_RGB, metallic=1.0, roughness=GLOSSY_METAL_ROUGHNESS)
    cornell.add_cornell_geometry(w, block_materials=("white", "metal"))
    classic_point_light(w)
    cornell.add_cornell_camera(w)
    return w


def build_double_sided():
    return cornell_scene(classic_point_light, double_sided=True, texcoords=True)


# 10 % of the box's height under the ceiling, in the Cornell data's millimetres.
LOW_LIGHT_DROP_MM = 0.1 * cornell.CORNELL_CEILING_Y_MM


def build_low_light():
    return cornell_scene(lambda w: classic_point_light(w, drop_mm=LOW_LIGHT_DROP_MM))


# x10 in every length: radiance (I / d^2) stays the same when I grows x100.
X10_SCALE = 10.0


def build_x10():
    return cornell_scene(lambda w: classic_point_light(w, scale=X10_SCALE), scale=X10_SCALE)


# The spot hangs where the point light does, pointing straight down, as strong on its axis.
# From there the floor's edges are 27 degrees off the axis and its corners 36 degrees: the
# inner cone (30 degrees) lights the floor at full strength out to its edges, the outer one
# (45 degrees) takes in the corners and the lowest part of the walls.
SPOT_INNER_DEG = 30.0
SPOT_OUTER_DEG = 45.0


def build_spot():
    def spot(w):
        w.add_spot_light_node("ceiling_spot", cornell.cornell_light_position(), (0.0, -1.0, 0.0),
                              WHITE, cornell.CORNELL_LIGHT_INTENSITY,
                              math.radians(SPOT_INNER_DEG), math.radians(SPOT_OUTER_DEG))
    return cornell_scene(spot)


# The sun travels into the box through its open front (+z side, where the camera is), down at
# about 34 degrees and a little towards the red wall: it lights the floor out to the back wall,
# the back wall's lowest 16 cm and part of the red wall, while the green wall shades a wedge of
# the floor.  2 W/m^2 gives the floor about 1.1 W/m^2, near what the point light gives it.
SUN_DIRECTION = (-0.3, -0.7, -1.0)
SUN_IRRADIANCE = 2.0
# The box's walls, ceiling and back get an outer side 2 cm out, closed along the open front by a
# rim: the sun lights the outside white (single-sided quads would leave it black) and its
# shadow starts 2 cm inside the ceiling, not at the back of a zero-thickness quad.
SHELL_THICKNESS_M = 0.02
GROUND_MARGIN_M = 1.0              # ground around the box's footprint on every side
GROUND_ALBEDO = (0.5, 0.5, 0.5)
OUTSIDE_CAMERA_EYE = (1.3, 1.1, 2.0)
OUTSIDE_CAMERA_TARGET = (0.278, 0.2, -0.3)
OUTSIDE_CAMERA_YFOV_DEG = 40.0


def cornell_outer_shell():
    """Outward faces T = SHELL_THICKNESS_M outside the walls, ceiling and back wall, and the
    rim that closes the gap between them at the open front (z = 0)."""
    t = SHELL_THICKNESS_M
    x1 = cornell.CORNELL_BOX_WIDTH_MM / 1000.0
    y1 = CORNELL_HEIGHT_M
    z0 = -cornell.CORNELL_BACK_WALL[0][2] / 1000.0
    shell = MeshBuilder()
    # No bottom (it stands on the ground) and no front (the box is open there).
    shell.add_box((-t, 0.0, z0 - t), (x1 + t, y1 + t, 0.0), inward=False, skip=[(1, 0), (2, 1)])
    # The red wall leans: its front edge runs from x = 3.2 mm at the floor to 0 at the ceiling.
    red_bottom, red_top = (cornell.cornell_to_gltf(p) for p in
                           (cornell.CORNELL_LEFT_WALL_RED[0], cornell.CORNELL_LEFT_WALL_RED[3]))
    front = (0.0, 0.0, 1.0)
    shell.add_quad([(-t, 0.0, 0.0), red_bottom, red_top, (-t, y1, 0.0)], front)
    shell.add_quad([(x1, 0.0, 0.0), (x1 + t, 0.0, 0.0), (x1 + t, y1, 0.0), (x1, y1, 0.0)], front)
    shell.add_quad([(-t, y1, 0.0), (x1 + t, y1, 0.0), (x1 + t, y1 + t, 0.0), (-t, y1 + t, 0.0)],
                   front)
    return shell


def build_open_front_sun():
    def sun(w):
        w.add_directional_light_node("sun", SUN_DIRECTION, WHITE, SUN_IRRADIANCE)

    w = cornell_scene(sun)
    w.add_mesh_node("outer_shell", cornell_outer_shell(), "white")
    w.add_material("ground", GROUND_ALBEDO)
    x0, x1 = 0.0, cornell.CORNELL_BOX_WIDTH_MM / 1000.0
    z0, z1 = -cornell.CORNELL_BACK_WALL[0][2] / 1000.0, 0.0
    g = GROUND_MARGIN_M
    ground = MeshBuilder()
    # Four strips around the box's floor, so no ground lies under it.
    for (a, b), (c, d) in (((x0 - g, x1 + g), (z1, z1 + g)), ((x0 - g, x1 + g), (z0 - g, z0)),
                           ((x0 - g, x0), (z0, z1)), ((x1, x1 + g), (z0, z1))):
        ground.add_quad([(a, 0.0, c), (b, 0.0, c), (b, 0.0, d), (a, 0.0, d)], (0.0, 1.0, 0.0))
    w.add_mesh_node("ground", ground, "ground")
    add_look_at_camera(w, "outside_camera", OUTSIDE_CAMERA_EYE, OUTSIDE_CAMERA_TARGET,
                       OUTSIDE_CAMERA_YFOV_DEG, 30.0)
    return w


def add_look_at_camera(w, name, eye, target, yfov_deg, zfar):
    w.add_camera_node(name, eye, math.radians(yfov_deg), 0.01, zfar,
                      look_rotation(sub(target, eye)))


# Two rooms side by side along x, the shared wall in the middle (see the module docstring).
ROOM_WIDTH = 2.0
ROOM_DEPTH = 4.5
ROOM_HEIGHT = 2.5
ROOM_ALBEDO = (0.8, 0.8, 0.8)
ROOM_LIGHT_HEIGHT = 2.0
ROOM_LIGHT_INTENSITY = 2.0         # W/sr: about 1.3 W/m^2 on the floor under it
VOXEL_RESOLUTION = 32              # voxel.resolution's default


def adaptive_finest_voxel(size):
    """The adaptive plan's finest voxel edge for a scene of bounds `size` (m), for a scene too
    long for one level (ResourcePlan.cpp, adaptiveVoxelPlan; voxel.size = 0)."""
    longest = max(size)
    shortest = max(min(size), longest / 8.0)
    coarsest = 2.0 * longest * 1.1
    levels = 1 + math.ceil(math.log2(coarsest / shortest) - 1e-6)
    assert longest * 1.1 > 1.25 * shortest, "one level would hold the whole scene"
    return coarsest / 2 ** (levels - 1) / VOXEL_RESOLUTION


def build_two_rooms():
    # The wall does not change the longest side (z) nor the shortest (y): see the docstring.
    t = adaptive_finest_voxel((2.0 * ROOM_WIDTH, ROOM_HEIGHT, ROOM_DEPTH))
    h, d = t / 2.0, ROOM_DEPTH / 2.0
    w = GltfWriter(GENERATOR)
    w.add_material("white", ROOM_ALBEDO)
    w.add_material("shared_wall", ROOM_ALBEDO)
    for name, sign in (("lit_room", -1.0), ("dark_room", 1.0)):
        inner, outer = sign * h, sign * (h + ROOM_WIDTH)
        lo, hi = (min(inner, outer), 0.0, -d), (max(inner, outer), ROOM_HEIGHT, d)
        shell = MeshBuilder()
        # No face on the shared wall's side (x = inner): the slab's face stands there.
        shell.add_box(lo, hi, inward=True, skip=[(0, 1 if sign < 0 else 0)])
        w.add_mesh_node(name, shell, "white")
    wall = MeshBuilder()
    wall.add_box((-h, 0.0, -d), (h, ROOM_HEIGHT, d), inward=False)
    w.add_mesh_node("shared_wall", wall, "shared_wall")
    assert abs(adaptive_finest_voxel([f32(b - a) for a, b in zip(w.bounds_min, w.bounds_max)])
               - t) < 1e-9

    w.add_point_light_node("lit_room_light", (-(h + ROOM_WIDTH / 2.0), ROOM_LIGHT_HEIGHT, 0.0),
                           WHITE, ROOM_LIGHT_INTENSITY)
    # Each camera stands in its room's outer front corner looking across at the shared wall.
    for name, sign in (("lit_room_camera", -1.0), ("dark_room_camera", 1.0)):
        eye = (sign * (h + ROOM_WIDTH - 0.25), 1.6, d - 0.3)
        add_look_at_camera(w, name, eye, (sign * h, 0.9, -0.8), 70.0, 20.0)
    return w


CLOSED_BOX_HALF = 1.0
CLOSED_BOX_ALBEDO = (0.8, 0.8, 0.8)
CLOSED_BOX_LIGHT_INTENSITY = 1.0   # W/sr: 1 W/m^2 at the middle of every face


def build_closed_white_box():
    s = CLOSED_BOX_HALF
    w = GltfWriter(GENERATOR)
    w.add_material("white", CLOSED_BOX_ALBEDO)
    box = MeshBuilder()
    box.add_box((-s, 0.0, -s), (s, 2.0 * s, s), inward=True)
    w.add_mesh_node("box", box, "white")
    w.add_point_light_node("centre_light", (0.0, s, 0.0), WHITE, CLOSED_BOX_LIGHT_INTENSITY)
    # From near one top corner towards the opposite lower edge: three faces in view.
    add_look_at_camera(w, "camera", (0.7 * s, 1.5 * s, 0.8 * s), (-0.6 * s, 0.5 * s, -s), 75.0,
                       10.0)
    return w


SCENES = [
    ("cornell_classic", build_classic),
    ("cornell_double_sided", build_double_sided),
    ("cornell_glossy", build_glossy),
    ("cornell_low_light", build_low_light),
    ("cornell_x10", build_x10),
    ("cornell_spot", build_spot),
    ("cornell_open_front_sun", build_open_front_sun),
    ("two_rooms_thin_wall", build_two_rooms),
    ("closed_white_box", build_closed_white_box),
]


def main(argv):
    if argv not in ([], ["--check"]):
        print(__doc__.strip().split("\n\n")[-2], file=sys.stderr)
        return 2
    check = argv == ["--check"]
    files = {}
    for name, build in SCENES:
        writer = build()
        files[name + ".gltf"] = (writer, writer.finish(name))
    stale = sorted(f for f in os.listdir(HERE) if f.endswith(".gltf") and f not in files)
    differ = []
    for name, (writer, data) in files.items():
        path = os.path.join(HERE, name)
        if not os.path.isfile(path) or open(path, "rb").read() != data:
            differ.append(name)
    if check:
        for name in differ + stale:
            print("assets/scene_suite/%s does not match make_scene_suite.py" % name)
        return 1 if differ or stale else 0
    for name in stale:
        os.remove(os.path.join(HERE, name))
    for name, (writer, data) in files.items():
        path = os.path.join(HERE, name)
        if name in differ:
            write_atomically(path, data)
        print(writer.summary(path, data))
    print("%d scenes, %d written, %d removed" % (len(files), len(differ), len(stale)))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
