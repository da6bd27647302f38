#!/usr/bin/env python3
"""Where the upper plate meets a seated SPB rock: the highest vertices of its surface.

Usage: topContacts.py <case> [<case> ...]
Reads <case>/constant/triSurface/specimen.stl (ASCII, written by meshRock, the rock seated
on its lower plate, z up) and prints, for each case, the depth below the highest vertex of
the next three vertices and their horizontal distance from it. A second vertex a few tenths
of a millimetre down, far from the first, makes the top nearly an edge or a facet: a blunt
apex under the plate (docs/validation.md section 3, "Which rocks over-predict most").
Standard library only.
"""
import math
import sys


def vertices(stlPath):
    points = set()
    with open(stlPath) as stl:
        for line in stl:
            words = line.split()
            if words and words[0] == "vertex":
                points.add(tuple(float(w) for w in words[1:4]))
    return sorted(points, key=lambda p: -p[2])


print("# case\tvertices [-]\tdepth [mm] @ horizontal distance [mm] of the 2nd, 3rd and 4th highest vertex")
for case in sys.argv[1:]:
    points = vertices(case + "/constant/triSurface/specimen.stl")
    top = points[0]
    below = ["%.2f@%.0f" % ((top[2] - p[2]) * 1e3, math.hypot(p[0] - top[0], p[1] - top[1]) * 1e3)
             for p in points[1:4]]
    print("%s\t%d\t%s" % (case, len(points), "\t".join(below)))
