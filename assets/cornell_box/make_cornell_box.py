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
import base64
import json
import math
import os
import struct
import sys

GENERATOR = "voxatlas make_cornell_box.py"

# glTF enums.
FLOAT = 5126
UNSIGNED_SHORT = 5123
ARRAY_BUFFER = 34962
ELEMENT_ARRAY_BUFFER = 34963

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


def cornell_to_gltf(p):
    """Cornell millimetres -> glTF metres.

    Mirroring z alone would give the camera its glTF -Z view direction but
    would also reflect the scene (red wall on the right).  Mirroring x as well
    turns the change into a rotation by 180 degrees about the vertical line
    x = 278 mm, z = 0, which keeps handedness, windings and the photographed
    left/right layout.  x is mirrored about the box's widest extent (556 mm)
    so that every x stays in [0, 0.556] and the camera stays at x = 0.278.
    """
    x, y, z = p
    # "+ 0.0" turns -0.0 (from z = 0) into 0.0 so the file never shows "-0.0".
    return ((CORNELL_BOX_WIDTH_MM - x) / 1000.0, y / 1000.0, -z / 1000.0 + 0.0)


# --------------------------------------------------------------------------
# Small vector helpers.
# --------------------------------------------------------------------------
def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def normalize(a):
    n = math.sqrt(dot(a, a))
    return (a[0] / n, a[1] / n, a[2] / n)


def mean(points):
    k = float(len(points))
    return tuple(sum(p[i] for p in points) / k for i in range(3))


def f32(v):
    """The value v takes once stored as a 32-bit float (for accessor min/max)."""
    return struct.unpack("<f", struct.pack("<f", v))[0]


def triangle_normal(a, b, c):
    return normalize(cross(sub(b, a), sub(c, a)))


def newell_normal(poly):
    """Area-weighted normal of a polygon (robust for slightly non-planar quads)."""
    n = [0.0, 0.0, 0.0]
    for i, cur in enumerate(poly):
        nxt = poly[(i + 1) % len(poly)]
        n[0] += (cur[1] - nxt[1]) * (cur[2] + nxt[2])
        n[1] += (cur[2] - nxt[2]) * (cur[0] + nxt[0])
        n[2] += (cur[0] - nxt[0]) * (cur[1] + nxt[1])
    return normalize(tuple(n))


# --------------------------------------------------------------------------
# Mesh building.
# --------------------------------------------------------------------------
class MeshBuilder:
    """Flat-shaded triangles: every face owns its vertices and one normal."""

    def __init__(self):
        self.positions = []
        self.normals = []
        self.indices = []

    def add_quad(self, quad, facing):
        """Add a quad whose front side faces along `facing` (a direction).

        The quad is reordered so that it is counter-clockwise seen from that
        side, then split along its 0-2 diagonal.  A planar quad shares four
        vertices; a non-planar one (the Cornell red wall is off by ~3 mm) gets
        two triangles with their own exact normals.
        """
        quad = list(quad)
        if dot(newell_normal(quad), facing) < 0.0:
            quad.reverse()
        tris = [(quad[0], quad[1], quad[2]), (quad[0], quad[2], quad[3])]
        normals = [triangle_normal(*t) for t in tris]
        if max(abs(normals[0][i] - normals[1][i]) for i in range(3)) < 1e-9:
            self._add_face(quad, normals[0], [(0, 1, 2), (0, 2, 3)])
        else:
            for tri, n in zip(tris, normals):
                self._add_face(list(tri), n, [(0, 1, 2)])

    def _add_face(self, verts, normal, local_tris):
        base = len(self.positions)
        self.positions.extend(verts)
        self.normals.extend([normal] * len(verts))
        for t in local_tris:
            self.indices.extend(base + i for i in t)

    @property
    def triangle_count(self):
        return len(self.indices) // 3


class GltfWriter:
    """Accumulates a glTF document with one embedded buffer."""

    def __init__(self):
        self.blob = bytearray()
        self.doc = {
            "asset": {"version": "2.0", "generator": GENERATOR},
            "extensionsUsed": ["KHR_lights_punctual"],
            "scene": 0,
            "scenes": [],
            "nodes": [],
            "meshes": [],
            "materials": [],
            "cameras": [],
            "accessors": [],
            "bufferViews": [],
            "buffers": [],
            "extensions": {"KHR_lights_punctual": {"lights": []}},
        }
        self.material_index = {}
        self.triangles = 0
        self.bounds_min = [math.inf] * 3
        self.bounds_max = [-math.inf] * 3

    def _view(self, data, target):
        # Every view starts on a 4-byte boundary, which covers the alignment
        # that float (4) and uint16 (2) accessors need.
        while len(self.blob) % 4:
            self.blob.append(0)
        view = {"buffer": 0, "byteOffset": len(self.blob), "byteLength": len(data)}
        if target is not None:  # animation data is neither vertices nor indices
            view["target"] = target
        self.doc["bufferViews"].append(view)
        self.blob.extend(data)
        return len(self.doc["bufferViews"]) - 1

    def _accessor(self, view, component_type, count, kind, extra=None):
        acc = {"bufferView": view, "byteOffset": 0, "componentType": component_type,
               "count": count, "type": kind}
        if extra:
            acc.update(extra)
        self.doc["accessors"].append(acc)
        return len(self.doc["accessors"]) - 1

    def add_material(self, name, rgb):
        self.material_index[name] = len(self.doc["materials"])
        self.doc["materials"].append({
            "name": name,
            "pbrMetallicRoughness": {
                "baseColorFactor": [rgb[0], rgb[1], rgb[2], 1.0],
                "metallicFactor": 0.0,
                "roughnessFactor": 1.0,
            },
        })

    def add_mesh_node(self, name, mesh, material):
        pos32 = [tuple(f32(c) for c in p) for p in mesh.positions]
        lo = [min(p[i] for p in pos32) for i in range(3)]
        hi = [max(p[i] for p in pos32) for i in range(3)]
        for i in range(3):
            self.bounds_min[i] = min(self.bounds_min[i], lo[i])
            self.bounds_max[i] = max(self.bounds_max[i], hi[i])
        n = len(mesh.positions)
        pos_view = self._view(b"".join(struct.pack("<3f", *p) for p in mesh.positions), ARRAY_BUFFER)
        nrm_view = self._view(b"".join(struct.pack("<3f", *v) for v in mesh.normals), ARRAY_BUFFER)
        idx_view = self._view(struct.pack("<%dH" % len(mesh.indices), *mesh.indices), ELEMENT_ARRAY_BUFFER)
        pos_acc = self._accessor(pos_view, FLOAT, n, "VEC3", {"min": lo, "max": hi})
        nrm_acc = self._accessor(nrm_view, FLOAT, n, "VEC3")
        idx_acc = self._accessor(idx_view, UNSIGNED_SHORT, len(mesh.indices), "SCALAR")
        self.doc["meshes"].append({
            "name": name,
            "primitives": [{
                "attributes": {"POSITION": pos_acc, "NORMAL": nrm_acc},
                "indices": idx_acc,
                "material": self.material_index[material],
                "mode": 4,
            }],
        })
        self.triangles += mesh.triangle_count
        return self._node({"name": name, "mesh": len(self.doc["meshes"]) - 1})

    def add_point_light_node(self, name, position, color, intensity):
        lights = self.doc["extensions"]["KHR_lights_punctual"]["lights"]
        lights.append({"name": name, "type": "point", "color": list(color), "intensity": intensity})
        return self._node({"name": name, "translation": list(position),
                           "extensions": {"KHR_lights_punctual": {"light": len(lights) - 1}}})

    def add_camera_node(self, name, position, yfov, znear, zfar, rotation=None):
        self.doc["cameras"].append({
            "name": name,
            "type": "perspective",
            "perspective": {"yfov": yfov, "znear": znear, "zfar": zfar},
        })
        node = {"name": name, "camera": len(self.doc["cameras"]) - 1}
        if rotation is not None:
            node["rotation"] = list(rotation)
        node["translation"] = list(position)
        return self._node(node)

    def add_animation(self, name, node, path, times, values, interpolation="LINEAR"):
        """One channel moving `node`'s `path` through `values` (tuples) at `times` (s)."""
        t_view = self._view(struct.pack("<%df" % len(times), *times), None)
        t_acc = self._accessor(t_view, FLOAT, len(times), "SCALAR",
                               {"min": [min(times)], "max": [max(times)]})
        width = len(values[0])
        flat = [c for v in values for c in v]
        v_view = self._view(struct.pack("<%df" % len(flat), *flat), None)
        v_acc = self._accessor(v_view, FLOAT, len(values), "VEC%d" % width)
        self.doc.setdefault("animations", []).append({
            "name": name,
            "samplers": [{"input": t_acc, "output": v_acc, "interpolation": interpolation}],
            "channels": [{"sampler": 0, "target": {"node": node, "path": path}}],
        })

    def _node(self, node):
        self.doc["nodes"].append(node)
        return len(self.doc["nodes"]) - 1

    def finish(self, scene_name):
        while len(self.blob) % 4:
            self.blob.append(0)
        self.doc["scenes"].append({"name": scene_name, "nodes": list(range(len(self.doc["nodes"])))})
        self.doc["buffers"].append({
            "byteLength": len(self.blob),
            "uri": "data:application/octet-stream;base64," + base64.b64encode(bytes(self.blob)).decode("ascii"),
        })
        return (json.dumps(self.doc, indent=2) + "\n").encode("utf-8")


# --------------------------------------------------------------------------
# Scenes.
# --------------------------------------------------------------------------
def build_cornell():
    w = GltfWriter()
    for name, rgb in CORNELL_MATERIALS:
        w.add_material(name, rgb)

    def conv(quad):
        return [cornell_to_gltf(p) for p in quad]

    # Room surfaces face the inside of the box: towards the centre of its
    # bounding box.
    room_centre = cornell_to_gltf((CORNELL_BOX_WIDTH_MM / 2.0, CORNELL_CEILING_Y_MM / 2.0, 559.2 / 2.0))
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
        w.add_mesh_node(name, m, material)

    # Block faces face away from the block's centre.  No bottom faces: they
    # rest on the floor and are never seen.
    for name, faces in (("short_block", CORNELL_SHORT_BLOCK), ("tall_block", CORNELL_TALL_BLOCK)):
        quads = [conv(f) for f in faces]
        centre = mean([p for q in quads for p in q])
        m = MeshBuilder()
        for q in quads:
            m.add_quad(q, sub(mean(q), centre))
        w.add_mesh_node(name, m, "white")

    lx, _, lz = cornell_to_gltf(mean(CORNELL_LIGHT))
    light_pos = (round(lx, 6), round((CORNELL_CEILING_Y_MM - CORNELL_LIGHT_DROP_MM) / 1000.0, 6), round(lz, 6))
    w.add_point_light_node("ceiling_light", light_pos, (1.0, 1.0, 1.0), CORNELL_LIGHT_INTENSITY)

    # Published camera: 35 mm lens, 25 mm film -> yfov = 2 atan(12.5 / 35).
    # After the conversion it looks down -Z with +Y up, glTF's default
    # camera orientation, so the node needs no rotation.
    cam_pos = tuple(round(c, 6) for c in cornell_to_gltf(CORNELL_CAMERA_MM))
    yfov = 2.0 * math.atan(0.5 * CORNELL_FILM_HEIGHT_M / CORNELL_FOCAL_LENGTH_M)
    w.add_camera_node("camera", cam_pos, yfov, 0.01, 10.0)
    return w, "cornell_box"


# Analytic test scene: radiance of the floor is rho/pi * I cos(theta) / d^2.
PLANE_HALF_SIZE = 1.0
PLANE_ALBEDO = 0.5
PLANE_LIGHT_POS = (0.0, 1.0, 0.0)
PLANE_LIGHT_INTENSITY = 1.0
PLANE_CAMERA_POS = (0.0, 1.0, 2.2)
PLANE_CAMERA_YFOV_DEG = 45.0


def build_plane():
    w = GltfWriter()
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

    # Write beside the target and rename, so a failed run never leaves a
    # truncated file that looks like a good one.
    out_dir = os.path.dirname(os.path.abspath(out))
    os.makedirs(out_dir, exist_ok=True)
    tmp = out + ".tmp"
    with open(tmp, "wb") as f:
        f.write(data)
    os.replace(tmp, out)

    lo = ", ".join("%.4f" % v for v in writer.bounds_min)
    hi = ", ".join("%.4f" % v for v in writer.bounds_max)
    print("%s: %d triangles, %d meshes, bounds min (%s) max (%s) m, %d bytes"
          % (out, writer.triangles, len(writer.doc["meshes"]), lo, hi, len(data)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
