#!/usr/bin/env python3
"""A closed ASCII STL icosphere of radius 20 (mm): icosphere.py <kind> <subdivisions> <file>
kind: sphere; dented (the cap above z = 6 folded inwards into a crater: a concave rock);
noisy (each coordinate scaled by 1 +- up to 0.5 %, seed 1: a scan-like surface whose convex
hull has many thin, nearly coplanar facets)."""
import math
import random
import sys

kind, n, out = sys.argv[1], int(sys.argv[2]), sys.argv[3]
t = (1 + 5 ** 0.5) / 2
V = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t), (0, -1, -t), (0, 1, -t),
     (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
F = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2), (10, 7, 6),
     (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7),
     (9, 8, 1)]
unit = lambda v: tuple(c / math.sqrt(sum(x * x for x in v)) for c in v)
V = [unit(v) for v in V]
for _ in range(n):
    middle, G = {}, []
    def mid(a, b):
        k = (min(a, b), max(a, b))
        if k not in middle:
            V.append(unit(tuple((V[a][i] + V[b][i]) / 2 for i in range(3))))
            middle[k] = len(V) - 1
        return middle[k]
    for a, b, c in F:
        ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
        G += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
    F = G
R = 20.0
random.seed(1)
P = []
for v in V:
    p = [R * c for c in v]
    if kind == "dented" and v[2] > 0.3:
        p[2] = R * 0.3 - (R * v[2] - R * 0.3) * 0.8  # the cap folded inwards: a crater
    if kind == "noisy":
        p = [R * (1 + 0.005 * random.uniform(-1, 1)) * c for c in v]
    P.append(p)
with open(out, "w") as f:
    f.write("solid rock\n")
    for tri in F:
        f.write("facet normal 0 0 0\nouter loop\n")
        for i in tri:
            f.write("vertex %.9g %.9g %.9g\n" % tuple(P[i]))
        f.write("endloop\nendfacet\n")
    f.write("endsolid rock\n")
