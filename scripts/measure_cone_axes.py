#!/usr/bin/env python3
"""How much of the cosine-weighted hemisphere the axes of the 19 diffuse cones
(src/gi/voxel/ConeSet.h) give a sunlit floor, seen from a vertical wall standing on it,
against the exact share: a point of a wall at z = 0.1 facing +Z, at each height, over the floor
y = 0 with |x|, |z| <= 1 (a 0.2 m block on a 2 m floor). Cone tracing reads a cone's light
where its axis meets a surface, so this is the share the cone set would give if every cone
stopped at the floor it crosses (docs/accuracy-analysis.md, 'Cones that passed through floors').
    /usr/bin/python3 scripts/measure_cone_axes.py
"""
import numpy as np


def hits_floor(origin, dirs):
    t = -origin[1] / np.minimum(dirs[..., 1], -1e-9)
    p = origin + dirs * t[..., None]
    return (dirs[..., 1] < 0) & (np.abs(p[..., 0]) <= 1) & (np.abs(p[..., 2]) <= 1)


def main():
    rng = np.random.default_rng(1)
    n, t, b = np.array([0, 0, 1.0]), np.array([-1.0, 0, 0]), np.array([0, -1.0, 0])
    rings = ((6, 4 / 19), (12, 13 / 19))   # cones, sin^2 of the elevation (equal shares)
    print("| height (m) | exact share | the axes' share, mean over ring turns | ratio |")
    print("|---:|---:|---:|---:|")
    for h in (0.02, 0.05, 0.1, 0.15, 0.19):
        origin = np.array([0, h, 0.1])
        u1, u2 = rng.random(400000), rng.random(400000)
        r, phi = np.sqrt(u1), 2 * np.pi * u2
        d = (np.sqrt(1 - u1)[:, None] * n + (r * np.cos(phi))[:, None] * t
             + (r * np.sin(phi))[:, None] * b)
        exact = hits_floor(origin, d).mean()
        shares = []
        for turn in np.linspace(0, 1, 64, endpoint=False):
            share = hits_floor(origin, n[None, :])[0] / 19
            for k, (count, sine2) in enumerate(rings):
                phis = (np.arange(count) + 0.5 * k + turn) * 2 * np.pi / count
                dirs = (np.sqrt(1 - sine2) * n + np.sqrt(sine2)
                        * (np.cos(phis)[:, None] * t + np.sin(phis)[:, None] * b))
                share += hits_floor(origin, dirs).sum() / 19
            shares.append(share)
        print("| %.2f | %.3f | %.3f | %.3f |" % (h, exact, np.mean(shares), np.mean(shares) / exact))


if __name__ == "__main__":
    main()
