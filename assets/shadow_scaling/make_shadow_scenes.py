#!/usr/bin/env python3
"""Write the shadow-scaling scenes: a grey ground lit only by an emissive panel above it,
with displaced spheres of 69,600 triangles each standing on it as instances of one mesh, so
the triangle count grows while the file stays small. They measure how shadow rays scale with
geometry (shadow.method, docs/results-linespace.md), as the line-space paper's scenes do
(Bunny 69 k, Buddha 1.09 M, Dragon + Buddha 1.96 M triangles).

  spheres_70k    1 sphere     69,602 triangles with the ground and the panel
  spheres_1m    16 spheres  1,113,602
  spheres_2m    28 spheres  1,948,802

Usage:  make_shadow_scenes.py OUT_DIR     writes OUT_DIR/spheres_*.gltf (deterministic bytes)
The files are generated where they are needed, not committed.
"""
import math
import os
import sys

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from gltf_builder import GltfWriter, MeshBuilder, write_atomically  # noqa: E402

GENERATOR = "voxatlas assets/shadow_scaling/make_shadow_scenes.py"
RINGS, SEGMENTS = 150, 232       # 2 x 150 x 232 = 69,600 triangles per sphere
RADIUS = 0.5
SPACING = 1.4
SCENES = [("spheres_70k", 1), ("spheres_1m", 16), ("spheres_2m", 28)]


def displacement(theta, phi):
    """A smooth bumpy relief, up to 8% of the radius: enough to cast self-shadows."""
    return 1.0 + 0.05 * math.sin(7.0 * theta) * math.cos(5.0 * phi) + 0.03 * math.sin(13.0 * phi + 3.0 * theta)


def displaced_sphere():
    mesh = MeshBuilder()
    grid = []
    for i in range(RINGS + 1):
        theta = math.pi * i / RINGS
        row = []
        for j in range(SEGMENTS + 1):
            phi = 2.0 * math.pi * j / SEGMENTS
            r = RADIUS * displacement(theta, phi)
            p = (r * math.sin(theta) * math.cos(phi), RADIUS + r * math.cos(theta),
                 r * math.sin(theta) * math.sin(phi))
            row.append(len(mesh.positions))
            mesh.positions.append(p)
            n = (math.sin(theta) * math.cos(phi), math.cos(theta), math.sin(theta) * math.sin(phi))
            mesh.normals.append(n)
            mesh.texcoords.append((j / SEGMENTS, i / RINGS))
        grid.append(row)
    for i in range(RINGS):
        for j in range(SEGMENTS):
            a, b, c, d = grid[i][j], grid[i + 1][j], grid[i + 1][j + 1], grid[i][j + 1]
            mesh.indices.extend((a, d, b, b, d, c))   # counter-clockwise seen from outside
    return mesh


def build(count, sphere):
    w = GltfWriter(GENERATOR)
    w.add_material("grey", (0.6, 0.6, 0.6))
    w.add_material("panel", (0.0, 0.0, 0.0), emissive=(1.0, 1.0, 1.0), emissive_strength=20.0)
    columns = math.ceil(math.sqrt(count))
    rows = math.ceil(count / columns)
    half_x = 0.5 * columns * SPACING + 1.0
    half_z = 0.5 * rows * SPACING + 1.0
    ground = MeshBuilder()
    ground.add_quad([(-half_x, 0.0, -half_z), (half_x, 0.0, -half_z), (half_x, 0.0, half_z),
                     (-half_x, 0.0, half_z)], (0.0, 1.0, 0.0))
    w.add_mesh_node("ground", ground, "grey")
    size = max(half_x, half_z)
    height = 1.5 + 0.6 * size
    panel = MeshBuilder()
    panel.add_quad([(-0.3 * size, height, -0.3 * size), (0.3 * size, height, -0.3 * size),
                    (0.3 * size, height, 0.3 * size), (-0.3 * size, height, 0.3 * size)],
                   (0.0, -1.0, 0.0))
    w.add_mesh_node("panel", panel, "panel")
    first = w.add_mesh_node("sphere_0", sphere, "grey")
    mesh = w.doc["nodes"][first]["mesh"]
    for k in range(count):
        x = (k % columns - 0.5 * (columns - 1)) * SPACING
        z = (k // columns - 0.5 * (rows - 1)) * SPACING
        if k == 0:
            w.doc["nodes"][first]["translation"] = [x, 0.0, z]
        else:
            w.add_node({"name": f"sphere_{k}", "mesh": mesh, "translation": [x, 0.0, z]})
    eye = (0.0, 0.45 * height + 0.5, 1.1 * half_z + 1.5)
    forward = (0.0, -eye[1] + 0.4, -eye[2])
    length = math.sqrt(sum(c * c for c in forward))
    pitch = math.asin(forward[1] / length)
    rotation = (math.sin(0.5 * pitch), 0.0, 0.0, math.cos(0.5 * pitch))
    w.add_camera_node("camera", eye, math.radians(50.0), 0.05, 100.0, rotation)
    return w


def main(argv):
    if len(argv) != 1:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    os.makedirs(argv[0], exist_ok=True)
    sphere = displaced_sphere()
    for name, count in SCENES:
        data = build(count, sphere).finish(name)
        write_atomically(os.path.join(argv[0], name + ".gltf"), data)
    print("%d scenes in %s" % (len(SCENES), argv[0]))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
