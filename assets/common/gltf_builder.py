"""Building blocks for the scenes voxatlas writes itself as self-contained glTF 2.0 files.

Flat-shaded meshes, Lambertian materials, KHR_lights_punctual lights and perspective cameras,
accumulated into one document with one embedded (base64) buffer.  Everything here is plain
arithmetic on Python floats and json.dumps of the result, so a script that uses it writes the
same bytes on every run.

Used by ../cornell_box/make_cornell_box.py and ../scene_suite/make_scene_suite.py, which add
this folder to sys.path.
"""

import base64
import json
import math
import os
import struct

# glTF enums.
FLOAT = 5126
UNSIGNED_SHORT = 5123
ARRAY_BUFFER = 34962
ELEMENT_ARRAY_BUFFER = 34963

# Texture coordinates of a face's corners, in the order add_quad stores them.
QUAD_UVS = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]


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


def look_rotation(forward, up=None):
    """Unit quaternion (x, y, z, w) turning a node's -Z onto `forward`, its +Y towards `up`.

    glTF cameras look, and spot and directional lights shine, along their node's -Z.  `up`
    defaults to +Y, or to -Z for a vertical `forward` (so a light pointing straight down
    keeps its +Y towards -Z).  Components are rounded to 9 decimals, which keeps the file
    independent of the last bit of the platform's sqrt and trigonometry.
    """
    f = normalize(forward)
    if up is None:
        up = (0.0, 0.0, -1.0) if abs(f[1]) > 0.999999 else (0.0, 1.0, 0.0)
    z = (-f[0], -f[1], -f[2])
    x = normalize(cross(up, z))
    y = cross(z, x)
    # Columns x, y, z of the rotation matrix -> quaternion (Shepperd's method).
    m00, m11, m22 = x[0], y[1], z[2]
    trace = m00 + m11 + m22
    if trace > 0.0:
        s = 2.0 * math.sqrt(trace + 1.0)
        q = ((y[2] - z[1]) / s, (z[0] - x[2]) / s, (x[1] - y[0]) / s, 0.25 * s)
    elif m00 > m11 and m00 > m22:
        s = 2.0 * math.sqrt(1.0 + m00 - m11 - m22)
        q = (0.25 * s, (y[0] + x[1]) / s, (z[0] + x[2]) / s, (y[2] - z[1]) / s)
    elif m11 > m22:
        s = 2.0 * math.sqrt(1.0 + m11 - m00 - m22)
        q = ((y[0] + x[1]) / s, 0.25 * s, (z[1] + y[2]) / s, (z[0] - x[2]) / s)
    else:
        s = 2.0 * math.sqrt(1.0 + m22 - m00 - m11)
        q = ((z[0] + x[2]) / s, (z[1] + y[2]) / s, 0.25 * s, (x[1] - y[0]) / s)
    return tuple(round(c, 9) + 0.0 for c in q)


# --------------------------------------------------------------------------
# Mesh building.
# --------------------------------------------------------------------------
class MeshBuilder:
    """Flat-shaded triangles: every face owns its vertices and one normal."""

    def __init__(self):
        self.positions = []
        self.normals = []
        self.texcoords = []
        self.indices = []

    def add_quad(self, quad, facing):
        """Add a quad whose front side faces along `facing` (a direction).

        The quad is reordered so that it is counter-clockwise seen from that
        side, then split along its 0-2 diagonal.  A planar quad shares four
        vertices; a non-planar one (the Cornell red wall is off by ~3 mm) gets
        two triangles with their own exact normals.  Texture coordinates map
        the face onto the unit square, corner by corner.
        """
        quad = list(quad)
        if dot(newell_normal(quad), facing) < 0.0:
            quad.reverse()
        tris = [(quad[0], quad[1], quad[2]), (quad[0], quad[2], quad[3])]
        normals = [triangle_normal(*t) for t in tris]
        if max(abs(normals[0][i] - normals[1][i]) for i in range(3)) < 1e-9:
            self._add_face(quad, normals[0], QUAD_UVS, [(0, 1, 2), (0, 2, 3)])
        else:
            corner_sets = [(0, 1, 2), (0, 2, 3)]
            for tri, n, corners in zip(tris, normals, corner_sets):
                self._add_face(list(tri), n, [QUAD_UVS[c] for c in corners], [(0, 1, 2)])

    def add_box(self, lo, hi, inward, skip=()):
        """The faces of the axis-aligned box lo..hi, facing in or out, but those in `skip`:
        (axis, 0) names the face at lo[axis], (axis, 1) the one at hi[axis]."""
        centre = mean([lo, hi])
        for axis in range(3):
            u, v = [i for i in range(3) if i != axis]
            for end, side in enumerate((lo, hi)):
                if (axis, end) in skip:
                    continue
                corners = []
                for cu, cv in ((lo[u], lo[v]), (hi[u], lo[v]), (hi[u], hi[v]), (lo[u], hi[v])):
                    p = [0.0, 0.0, 0.0]
                    p[axis], p[u], p[v] = side[axis], cu, cv
                    corners.append(tuple(p))
                outward = sub(mean(corners), centre)
                self.add_quad(corners, tuple(-c for c in outward) if inward else outward)

    def _add_face(self, verts, normal, uvs, local_tris):
        base = len(self.positions)
        self.positions.extend(verts)
        self.normals.extend([normal] * len(verts))
        self.texcoords.extend(uvs)
        for t in local_tris:
            self.indices.extend(base + i for i in t)

    @property
    def triangle_count(self):
        return len(self.indices) // 3


class GltfWriter:
    """Accumulates a glTF document with one embedded buffer."""

    def __init__(self, generator):
        self.blob = bytearray()
        self.doc = {
            "asset": {"version": "2.0", "generator": generator},
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

    def add_view(self, data, target, stride=None):
        """A buffer view over `data` (bytes); `stride` for interleaved vertex attributes."""
        view = self._view(data, target)
        if stride is not None:
            self.doc["bufferViews"][view]["byteStride"] = stride
        return view

    def add_accessor(self, view, component_type, count, kind, extra=None):
        return self._accessor(view, component_type, count, kind, extra)

    def add_node(self, node):
        return self._node(node)

    def add_material(self, name, rgb, double_sided=False, emissive=None, emissive_strength=None,
                     metallic=0.0, roughness=1.0):
        """`emissive`: the emissiveFactor (linear RGB); `emissive_strength`: its
        KHR_materials_emissive_strength multiplier, for radiance above 1 W/(m^2 sr);
        `metallic`, `roughness`: the glTF factors (a diffuse dielectric by default)."""
        self.material_index[name] = len(self.doc["materials"])
        material = {
            "name": name,
            "pbrMetallicRoughness": {
                "baseColorFactor": [rgb[0], rgb[1], rgb[2], 1.0],
                "metallicFactor": metallic,
                "roughnessFactor": roughness,
            },
        }
        if double_sided:
            material["doubleSided"] = True
        if emissive is not None:
            material["emissiveFactor"] = list(emissive)
        if emissive_strength is not None:
            material["extensions"] = {
                "KHR_materials_emissive_strength": {"emissiveStrength": emissive_strength}}
            if "KHR_materials_emissive_strength" not in self.doc["extensionsUsed"]:
                self.doc["extensionsUsed"].append("KHR_materials_emissive_strength")
        self.doc["materials"].append(material)

    def add_mesh_node(self, name, mesh, material, texcoords=False):
        """A node holding `mesh` as one primitive; TEXCOORD_0 too when `texcoords`."""
        pos32 = [tuple(f32(c) for c in p) for p in mesh.positions]
        lo = [min(p[i] for p in pos32) for i in range(3)]
        hi = [max(p[i] for p in pos32) for i in range(3)]
        for i in range(3):
            self.bounds_min[i] = min(self.bounds_min[i], lo[i])
            self.bounds_max[i] = max(self.bounds_max[i], hi[i])
        n = len(mesh.positions)
        pos_view = self._view(b"".join(struct.pack("<3f", *p) for p in mesh.positions),
                              ARRAY_BUFFER)
        nrm_view = self._view(b"".join(struct.pack("<3f", *v) for v in mesh.normals), ARRAY_BUFFER)
        if texcoords:
            uv_view = self._view(b"".join(struct.pack("<2f", *t) for t in mesh.texcoords),
                                 ARRAY_BUFFER)
        idx_view = self._view(struct.pack("<%dH" % len(mesh.indices), *mesh.indices),
                              ELEMENT_ARRAY_BUFFER)
        pos_acc = self._accessor(pos_view, FLOAT, n, "VEC3", {"min": lo, "max": hi})
        nrm_acc = self._accessor(nrm_view, FLOAT, n, "VEC3")
        attributes = {"POSITION": pos_acc, "NORMAL": nrm_acc}
        if texcoords:
            attributes["TEXCOORD_0"] = self._accessor(uv_view, FLOAT, n, "VEC2")
        idx_acc = self._accessor(idx_view, UNSIGNED_SHORT, len(mesh.indices), "SCALAR")
        self.doc["meshes"].append({
            "name": name,
            "primitives": [{
                "attributes": attributes,
                "indices": idx_acc,
                "material": self.material_index[material],
                "mode": 4,
            }],
        })
        self.triangles += mesh.triangle_count
        return self._node({"name": name, "mesh": len(self.doc["meshes"]) - 1})

    def _light_node(self, light, node):
        lights = self.doc["extensions"]["KHR_lights_punctual"]["lights"]
        lights.append(light)
        node["extensions"] = {"KHR_lights_punctual": {"light": len(lights) - 1}}
        return self._node(node)

    def add_point_light_node(self, name, position, color, intensity):
        """Intensity: radiant intensity, W/sr."""
        return self._light_node({"name": name, "type": "point", "color": list(color),
                                 "intensity": intensity},
                                {"name": name, "translation": list(position)})

    def add_spot_light_node(self, name, position, direction, color, intensity, inner, outer):
        """Intensity: radiant intensity on the axis, W/sr; cone angles in radians."""
        return self._light_node({"name": name, "type": "spot", "color": list(color),
                                 "intensity": intensity,
                                 "spot": {"innerConeAngle": inner, "outerConeAngle": outer}},
                                {"name": name, "rotation": list(look_rotation(direction)),
                                 "translation": list(position)})

    def add_directional_light_node(self, name, direction, color, intensity):
        """`direction`: where the light travels; intensity: irradiance, W/m^2."""
        return self._light_node({"name": name, "type": "directional", "color": list(color),
                                 "intensity": intensity},
                                {"name": name, "rotation": list(look_rotation(direction))})

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
        self.doc["scenes"].append({"name": scene_name,
                                   "nodes": list(range(len(self.doc["nodes"])))})
        self.doc["buffers"].append({
            "byteLength": len(self.blob),
            "uri": "data:application/octet-stream;base64,"
                   + base64.b64encode(bytes(self.blob)).decode("ascii"),
        })
        return (json.dumps(self.doc, indent=2) + "\n").encode("utf-8")

    def summary(self, path, data):
        """One line: path, triangle and mesh counts, bounds in metres, size in bytes."""
        lo = ", ".join("%.4f" % v for v in self.bounds_min)
        hi = ", ".join("%.4f" % v for v in self.bounds_max)
        return ("%s: %d triangles, %d meshes, bounds min (%s) max (%s) m, %d bytes"
                % (path, self.triangles, len(self.doc["meshes"]), lo, hi, len(data)))


def write_atomically(path, data):
    """Write beside the target and rename, so a failed run never leaves a
    truncated file that looks like a good one."""
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    tmp = path + ".tmp"
    with open(tmp, "wb") as f:
        f.write(data)
    os.replace(tmp, path)
