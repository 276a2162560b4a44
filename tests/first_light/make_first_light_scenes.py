#!/usr/bin/env python3
"""Write the first-light scenes: small glTF 2.0 files WITHOUT lights or cameras, of the kinds
ordinary sample models are, so tests can check that the defaults chosen from the geometry
(src/scene/SceneDefaults.h) show each of them lit.

  textured_box            a closed 1 m box, faces outward, a checker base colour texture
  triangle_no_indices     one triangle, positions only: no indices, no normals, no material
  sparse_plane            a vertical 3x3-vertex grid facing +Z whose positions come through
                          a sparse accessor (two vertices pushed out towards +Z)
  interleaved_box         a closed 1 m box, POSITION and NORMAL interleaved in one view
  vertex_colour_board     a vertical board facing +Z, its colours from COLOR_0
  ground_with_block       a 10 m ground facing up with a 1 m block on it (outdoor)
  closed_room             a 6 x 3 x 4 m room of inward faces with a block on its floor
                          (interior)

Usage:  make_first_light_scenes.py            (re)write every scene beside this script
        make_first_light_scenes.py --check    exit 1 if a committed scene differs from this
                                              script's

The output is deterministic: the same bytes on every run.
"""

import os
import struct
import sys
import zlib

sys.dont_write_bytecode = True  # no module cache left beside the files
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "assets", "common"))

from gltf_builder import (ARRAY_BUFFER, ELEMENT_ARRAY_BUFFER, FLOAT, UNSIGNED_SHORT,  # noqa: E402
                          GltfWriter, MeshBuilder, f32, write_atomically)

GENERATOR = "voxatlas make_first_light_scenes.py"
GREY = (0.8, 0.8, 0.8)


def png_rgb(width, height, pixel):
    """An 8-bit RGB PNG of pixel(x, y) -> (r, g, b); stored (uncompressed) deflate blocks,
    which every zlib writes byte for byte the same."""
    raw = b"".join(b"\x00" + bytes(c for x in range(width) for c in pixel(x, y))
                   for y in range(height))

    def chunk(tag, data):
        return (struct.pack(">I", len(data)) + tag + data
                + struct.pack(">I", zlib.crc32(tag + data) & 0xFFFFFFFF))

    header = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(raw, 0))
            + chunk(b"IEND", b""))


def without_lights_and_cameras(writer):
    """GltfWriter starts every document ready for lights and cameras; these have none."""
    for key in ("cameras", "extensionsUsed", "extensions"):
        writer.doc.pop(key, None)
    return writer


def add_raw_mesh(writer, name, attributes, indices=None, material=None):
    primitive = {"attributes": attributes, "mode": 4}
    if indices is not None:
        primitive["indices"] = indices
    if material is not None:
        primitive["material"] = writer.material_index[material]
    writer.doc["meshes"].append({"name": name, "primitives": [primitive]})
    return writer.add_node({"name": name, "mesh": len(writer.doc["meshes"]) - 1})


def position_accessor(writer, view, points, extra=None):
    pos32 = [tuple(f32(c) for c in p) for p in points]
    bounds = {"min": [min(p[i] for p in pos32) for i in range(3)],
              "max": [max(p[i] for p in pos32) for i in range(3)]}
    bounds.update(extra or {})
    return writer.add_accessor(view, FLOAT, len(points), "VEC3", bounds)


def floats(values):
    return struct.pack("<%df" % len(values), *values)


def textured_box():
    writer = GltfWriter(GENERATOR)
    writer.add_material("checker", (1.0, 1.0, 1.0))
    mesh = MeshBuilder()
    mesh.add_box((-0.5, -0.5, -0.5), (0.5, 0.5, 0.5), inward=False)
    writer.add_mesh_node("box", mesh, "checker", texcoords=True)
    texture = png_rgb(8, 8, lambda x, y: (230, 180, 60) if (x + y) % 2 else (60, 120, 220))
    writer.doc["images"] = [{"bufferView": writer.add_view(texture, None),
                             "mimeType": "image/png"}]
    writer.doc["samplers"] = [{"magFilter": 9728, "minFilter": 9728}]
    writer.doc["textures"] = [{"sampler": 0, "source": 0}]
    writer.doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {"index": 0}
    return without_lights_and_cameras(writer)


def triangle_no_indices():
    writer = GltfWriter(GENERATOR)
    points = [(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0)]
    view = writer.add_view(floats([c for p in points for c in p]), ARRAY_BUFFER)
    add_raw_mesh(writer, "triangle", {"POSITION": position_accessor(writer, view, points)})
    writer.doc.pop("materials")
    return without_lights_and_cameras(writer)


def sparse_plane():
    writer = GltfWriter(GENERATOR)
    writer.add_material("grey", GREY)
    grid = [(float(x), float(y), 0.0) for y in range(3) for x in range(3)]
    moved = {4: (1.0, 1.0, 0.4), 7: (1.0, 2.0, 0.2)}
    indices = []
    for y in range(2):
        for x in range(2):
            a, b, c, d = 3 * y + x, 3 * y + x + 1, 3 * (y + 1) + x + 1, 3 * (y + 1) + x
            indices += [a, b, c, a, c, d]
    base = writer.add_view(floats([c for p in grid for c in p]), ARRAY_BUFFER)
    sparse_indices = writer.add_view(struct.pack("<%dH" % len(moved), *sorted(moved)), None)
    sparse_values = writer.add_view(floats([c for i in sorted(moved) for c in moved[i]]), None)
    final = [moved.get(i, p) for i, p in enumerate(grid)]
    positions = position_accessor(writer, base, final, {"sparse": {
        "count": len(moved),
        "indices": {"bufferView": sparse_indices, "componentType": UNSIGNED_SHORT},
        "values": {"bufferView": sparse_values}}})
    index_view = writer.add_view(struct.pack("<%dH" % len(indices), *indices),
                                 ELEMENT_ARRAY_BUFFER)
    index_accessor = writer.add_accessor(index_view, UNSIGNED_SHORT, len(indices), "SCALAR")
    add_raw_mesh(writer, "plane", {"POSITION": positions}, index_accessor, "grey")
    return without_lights_and_cameras(writer)


def interleaved_box():
    writer = GltfWriter(GENERATOR)
    writer.add_material("grey", GREY)
    mesh = MeshBuilder()
    mesh.add_box((-0.5, -0.5, -0.5), (0.5, 0.5, 0.5), inward=False)
    data = b"".join(floats(list(p) + list(n)) for p, n in zip(mesh.positions, mesh.normals))
    view = writer.add_view(data, ARRAY_BUFFER, stride=24)
    positions = position_accessor(writer, view, mesh.positions)
    normals = writer.add_accessor(view, FLOAT, len(mesh.normals), "VEC3", {"byteOffset": 12})
    index_view = writer.add_view(struct.pack("<%dH" % len(mesh.indices), *mesh.indices),
                                 ELEMENT_ARRAY_BUFFER)
    index_accessor = writer.add_accessor(index_view, UNSIGNED_SHORT, len(mesh.indices), "SCALAR")
    add_raw_mesh(writer, "box", {"POSITION": positions, "NORMAL": normals}, index_accessor,
                 "grey")
    return without_lights_and_cameras(writer)


def vertex_colour_board():
    writer = GltfWriter(GENERATOR)
    writer.add_material("white", (1.0, 1.0, 1.0))
    points = [(-1.0, -0.5, 0.0), (1.0, -0.5, 0.0), (1.0, 0.5, 0.0), (-1.0, 0.5, 0.0)]
    colours = [(1.0, 0.2, 0.2, 1.0), (0.2, 1.0, 0.2, 1.0), (0.2, 0.2, 1.0, 1.0),
               (1.0, 1.0, 0.2, 1.0)]
    pos_view = writer.add_view(floats([c for p in points for c in p]), ARRAY_BUFFER)
    colour_view = writer.add_view(floats([c for q in colours for c in q]), ARRAY_BUFFER)
    index_view = writer.add_view(struct.pack("<6H", 0, 1, 2, 0, 2, 3), ELEMENT_ARRAY_BUFFER)
    attributes = {"POSITION": position_accessor(writer, pos_view, points),
                  "COLOR_0": writer.add_accessor(colour_view, FLOAT, 4, "VEC4")}
    add_raw_mesh(writer, "board", attributes,
                 writer.add_accessor(index_view, UNSIGNED_SHORT, 6, "SCALAR"), "white")
    return without_lights_and_cameras(writer)


def ground_with_block():
    writer = GltfWriter(GENERATOR)
    writer.add_material("grey", GREY)
    ground = MeshBuilder()
    ground.add_quad([(-5.0, 0.0, -5.0), (5.0, 0.0, -5.0), (5.0, 0.0, 5.0), (-5.0, 0.0, 5.0)],
                    (0.0, 1.0, 0.0))
    writer.add_mesh_node("ground", ground, "grey")
    block = MeshBuilder()
    block.add_box((-0.5, 0.0, -0.5), (0.5, 1.0, 0.5), inward=False)
    writer.add_mesh_node("block", block, "grey")
    return without_lights_and_cameras(writer)


def closed_room():
    writer = GltfWriter(GENERATOR)
    writer.add_material("grey", GREY)
    room = MeshBuilder()
    room.add_box((-3.0, 0.0, -2.0), (3.0, 3.0, 2.0), inward=True)
    writer.add_mesh_node("room", room, "grey")
    block = MeshBuilder()
    block.add_box((1.0, 0.0, -1.5), (2.0, 0.8, -0.5), inward=False)
    writer.add_mesh_node("block", block, "grey")
    return without_lights_and_cameras(writer)


SCENES = [
    ("textured_box", textured_box),
    ("triangle_no_indices", triangle_no_indices),
    ("sparse_plane", sparse_plane),
    ("interleaved_box", interleaved_box),
    ("vertex_colour_board", vertex_colour_board),
    ("ground_with_block", ground_with_block),
    ("closed_room", closed_room),
]


def main(argv):
    if argv not in ([], ["--check"]):
        print(__doc__.strip().split("\n\n")[-2], file=sys.stderr)
        return 2
    files = {name + ".gltf": build().finish(name) for name, build in SCENES}
    stale = sorted(f for f in os.listdir(HERE) if f.endswith(".gltf") and f not in files)
    differ = [name for name, data in files.items()
              if not os.path.isfile(os.path.join(HERE, name))
              or open(os.path.join(HERE, name), "rb").read() != data]
    if argv == ["--check"]:
        for name in differ + stale:
            print("tests/first_light/%s does not match make_first_light_scenes.py" % name)
        return 1 if differ or stale else 0
    for name in stale:
        os.remove(os.path.join(HERE, name))
    for name in differ:
        write_atomically(os.path.join(HERE, name), files[name])
    print("%d scenes, %d written, %d removed" % (len(files), len(differ), len(stale)))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
