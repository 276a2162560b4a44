#!/usr/bin/env python3
"""How much light the diffuse cones' directions give a point of the closed white box
(assets/scene_suite/closed_white_box.gltf: a 2 m cube, a point light at its centre), against
the exact cosine-weighted integral, if each cone read the light exactly where its axis meets a
wall. No voxels, no footprint, no opacity: what is left is the cone set's quadrature alone, the
rings' fixed elevations standing for their whole bands of the hemisphere (src/gi/voxel/ConeSet.h;
docs/accuracy-analysis.md, 'The closed white box's excess: the cone set's quadrature').

The radiance a wall sends is its irradiance from the light (cosine / distance squared; albedo and
intensity cancel in the ratio). For each receiver, on the floor, a wall and the ceiling, on a
grid of points, the exact integral is a Monte Carlo estimate over cosine-distributed directions
and each set's read is averaged over the turns the ring dither gives its rings.
    /usr/bin/python3 scripts/measure_cone_quadrature.py
"""
import numpy as np

LIGHT = np.array([0.0, 1.0, 0.0])
BOX_LOW, BOX_HIGH = np.array([-1.0, 0.0, -1.0]), np.array([1.0, 2.0, 1.0])

# (cones in the ring, sin^2 of its elevation, each cone's weight, the ring's band in sin^2);
# the central cone first.
NINETEEN = [(1, 0.0, 1 / 19, None), (6, 4 / 19, 1 / 19, (1 / 19, 7 / 19)),
            (12, 13 / 19, 1 / 19, (7 / 19, 1.0))]
THIRTY_SEVEN = [(1, 0.0, 1 / 37, None), (6, 4 / 37, 1 / 37, (1 / 37, 7 / 37)),
                (12, 16 / 37, 1 / 37, (7 / 37, 19 / 37)), (18, 28 / 37, 1 / 37, (19 / 37, 1.0))]
# name: (cone set, whether the rings move over their whole bands as the turns go round: the
# ideal of voxel.jitter_elevation, whose cones stop short of the horizon by their rims)
CONE_SETS = {
    "19 cones (default)": (NINETEEN, False),
    "37 cones": (THIRTY_SEVEN, False),
    "19 cones moved over their bands": (NINETEEN, True),
}
RECEIVERS = {
    "floor": (np.array([0.0, 1.0, 0.0]), lambda u, v: np.array([u, 0.0, v])),
    "ceiling": (np.array([0.0, -1.0, 0.0]), lambda u, v: np.array([u, 2.0, v])),
    "back wall": (np.array([0.0, 0.0, 1.0]), lambda u, v: np.array([u, 1.0 + v, -1.0])),
}


def wall_radiance(origin, dirs):
    """Irradiance from the light where rays from `origin` leave the box."""
    t_exit = np.full(len(dirs), np.inf)
    normal = np.zeros_like(dirs)
    for axis in range(3):
        d = dirs[:, axis]
        with np.errstate(divide="ignore", invalid="ignore"):
            t = np.where(d > 0, (BOX_HIGH[axis] - origin[axis]) / d,
                         np.where(d < 0, (BOX_LOW[axis] - origin[axis]) / d, np.inf))
        nearer = t < t_exit
        t_exit = np.where(nearer, t, t_exit)
        inward = np.zeros_like(dirs)
        inward[:, axis] = -np.sign(d)
        normal = np.where(nearer[:, None], inward, normal)
    hit = origin + dirs * t_exit[:, None]
    to_light = LIGHT - hit
    distance2 = (to_light * to_light).sum(axis=1)
    cosine = np.maximum((to_light * normal).sum(axis=1) / np.sqrt(distance2), 0.0)
    return cosine / distance2


def tangent_frame(normal):
    tangent = np.cross(normal, [0.3, 0.7, 0.2])
    tangent /= np.linalg.norm(tangent)
    return tangent, np.cross(normal, tangent)


def exact(origin, normal, rng, samples=200000):
    tangent, bitangent = tangent_frame(normal)
    u1, u2 = rng.random(samples), rng.random(samples)
    r, phi = np.sqrt(u1), 2 * np.pi * u2
    dirs = (np.sqrt(1 - u1)[:, None] * normal + (r * np.cos(phi))[:, None] * tangent
            + (r * np.sin(phi))[:, None] * bitangent)
    return wall_radiance(origin, dirs).mean()


def cone_read(origin, normal, cone_set, turns=16):
    cones, moved = cone_set
    tangent, bitangent = tangent_frame(normal)
    reads = []
    for step, turn in enumerate(np.linspace(0, 1, turns, endpoint=False)):
        total = 0.0
        for ring, (count, sine2, weight, band) in enumerate(cones):
            if moved and band is not None:   # a rank-1 lattice pairs each turn with a rise
                sine2 = band[0] + (band[1] - band[0]) * ((step * 7 % turns) + 0.5) / turns
            if count == 1:
                dirs = normal[None, :]
            else:
                phis = (np.arange(count) + 0.5 * ring + turn) * 2 * np.pi / count
                dirs = (np.sqrt(1 - sine2) * normal + np.sqrt(sine2)
                        * (np.cos(phis)[:, None] * tangent + np.sin(phis)[:, None] * bitangent))
            total += weight * wall_radiance(origin, dirs).sum()
        reads.append(total)
    return float(np.mean(reads))


def main():
    rng = np.random.default_rng(1)
    grid = np.linspace(-0.9, 0.9, 7)
    names = list(CONE_SETS)
    print("| receiver | " + " | ".join(names) + " |")
    print("|---|" + "---:|" * len(names))
    totals = {name: 0.0 for name in names}
    total_exact = 0.0
    for receiver, (normal, point) in RECEIVERS.items():
        exact_sum = 0.0
        sums = {name: 0.0 for name in names}
        for u in grid:
            for v in grid:
                origin = point(u, v) + normal * 1e-6
                exact_sum += exact(origin, normal, rng)
                for name in names:
                    sums[name] += cone_read(origin, normal, CONE_SETS[name])
        total_exact += exact_sum
        for name in names:
            totals[name] += sums[name]
        print("| %s | " % receiver + " | ".join("%.3f" % (sums[n] / exact_sum) for n in names)
              + " |")
    print("| all | " + " | ".join("%.3f" % (totals[n] / total_exact) for n in names) + " |")


if __name__ == "__main__":
    main()
