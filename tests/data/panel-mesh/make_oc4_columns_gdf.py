#!/usr/bin/env python3
"""Writes oc4-columns.gdf: the wetted surface (z <= 0) of the OC4-DeepCwind
columns of scenarios/oc4-semisubmersible.yaml (hull.geometry: main column,
three upper and three base columns; pontoons and braces left out) as a WAMIT
low-order panel mesh with ISY = 1 (only y >= 0 is written; the reader mirrors
it). Each column is a 24-sided prism; its side is cut into 1 panel per facet
and height band, its bottom into triangle fans (a repeated vertex), the base
columns' tops into annulus panels around the upper columns. Vertices are
ordered so that the normal (p2 - p0) x (p3 - p1) points into the water.
Run: python3 make_oc4_columns_gdf.py > oc4-columns.gdf
"""
import math

N = 24  # facets of a column
# (x, y, z_bottom, z_top, diameter) of the wetted columns (z_top clipped at 0)
COLUMNS = [
    (0.0, 0.0, -20.0, 0.0, 6.5),
    (14.434, 25.0, -14.0, 0.0, 12.0),
    (-28.868, 0.0, -14.0, 0.0, 12.0),
    (14.434, 25.0, -20.0, -14.0, 24.0),
    (-28.868, 0.0, -20.0, -14.0, 24.0),
]
UPPER_ON_BASE = {3: 12.0, 4: 12.0}  # base column index -> diameter of the column on its top
STANDING = {1, 2}  # upper columns: their bottom faces lie on the base columns' tops (not wetted)

panels = []


def ring(x, y, r, z):
    return [(x + r * math.cos(2 * math.pi * k / N), y + r * math.sin(2 * math.pi * k / N), z) for k in range(N + 1)]


def keep(points):
    # ISY = 1: keep the facets on y >= 0 (every column centre has y = 0 or y > r)
    return all(p[1] >= -1e-9 for p in points)


for i, (x, y, z0, z1, d) in enumerate(COLUMNS):
    r = d / 2
    lo, hi = ring(x, y, r, z0), ring(x, y, r, z1)
    for k in range(N):
        side = [lo[k], lo[k + 1], hi[k + 1], hi[k]]
        if keep(side):
            panels.append(side)
        bottom = [(x, y, z0), lo[k + 1], lo[k], lo[k]]  # seen from below: clockwise from above
        if i not in STANDING and keep(bottom):
            panels.append(bottom)
        if i in UPPER_ON_BASE:
            inner = ring(x, y, UPPER_ON_BASE[i] / 2, z1)
            top = [inner[k], hi[k], hi[k + 1], inner[k + 1]]
            if keep(top):
                panels.append(top)
        elif z1 < 0.0:
            top = [(x, y, z1), hi[k], hi[k + 1], hi[k + 1]]
            if keep(top):
                panels.append(top)

print("OC4-DeepCwind columns, wetted surface, half (y >= 0); spiral test data")
print("1.0 9.80665   ULEN GRAV")
print("0 1   ISX ISY")
print(f"{len(panels)}   NPAN")
for p in panels:
    for v in p:
        print(f"{v[0]:12.5f} {v[1]:12.5f} {v[2]:12.5f}")
