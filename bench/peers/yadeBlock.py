# The Yade peer of benchDem's intact bonded block (bench/run, docs/benchmarks.md).
#
#   yade -j<threads> -n -x bench/peers/yadeBlock.py <elements> <dt [s]> <steps>
#
# A block of <elements> equal spheres on a hexagonal close packing, each touching pair
# glued by a CohFrictMat cohesive bond (normal and shear cohesion 1e12 Pa, so nothing
# breaks, as in benchDem's block), the sphere volume equal to the BDT's Voronoi cell
# (meso constant 7.25e-8 m^3), the rock's density and the bond's Young's modulus of
# rockfrac's defaults, small random velocities, numerical damping 0.05, and the time
# step rockfrac uses for its block. Times <steps> steps (best of 3) and prints one line:
#   yade <spheres> <bonds> <threads> <steps> <seconds> <element-steps/s> <bond-evaluations/s> <dt> <p-wave dt>
# A sphere has ~6 bonds (12 neighbours), a Voronoi cell ~37 bond points: bench/run
# reports the ratio per element-step and per bond evaluation.
import math
import random
import sys
import time

from yade import O, pack, utils
from yade.wrapper import (CohFrictMat, ForceResetter, InsertionSortCollider, Bo1_Sphere_Aabb, InteractionLoop,
                          Ig2_Sphere_Sphere_ScGeom6D, Ip2_CohFrictMat_CohFrictMat_CohFrictPhys,
                          Law2_ScGeom6D_CohFrictPhys_CohesionMoment, NewtonIntegrator)

elements = int(sys.argv[1])
dt = float(sys.argv[2])
steps = int(sys.argv[3])

volume = 7.25e-8                                   # per element [m^3]
radius = (3.0 * volume / (4.0 * math.pi)) ** (1.0 / 3.0)
# Hexagonal close packing holds one sphere per 4 sqrt(2) r^3: a 2:1:1 box with ~elements spheres.
box_volume = elements * 4.0 * math.sqrt(2.0) * radius ** 3
side = (box_volume / 2.0) ** (1.0 / 3.0)

O.materials.append(CohFrictMat(young=46e9, poisson=0.25, density=2540.0, frictionAngle=0.5, isCohesive=True,
                               normalCohesion=1e12, shearCohesion=1e12, momentRotationLaw=True))
spheres = pack.regularHexa(pack.inAlignedBox((0, 0, 0), (2 * side, side, side)), radius=radius, gap=0)
for attempt in range(4):  # the lattice rounds the count: rescale the box towards <elements>
    if abs(len(spheres) - elements) <= 0.03 * elements:
        break
    side *= (elements / float(len(spheres))) ** (1.0 / 3.0)
    spheres = pack.regularHexa(pack.inAlignedBox((0, 0, 0), (2 * side, side, side)), radius=radius, gap=0)
O.bodies.append(spheres)
factor = 1.05  # bonds between spheres closer than 1.05 x the sum of their radii
O.engines = [
    ForceResetter(),
    InsertionSortCollider([Bo1_Sphere_Aabb(aabbEnlargeFactor=factor)], verletDist=0.1 * radius),
    InteractionLoop([Ig2_Sphere_Sphere_ScGeom6D(interactionDetectionFactor=factor)],
                    [Ip2_CohFrictMat_CohFrictMat_CohFrictPhys(setCohesionNow=True, setCohesionOnNewContacts=False)],
                    [Law2_ScGeom6D_CohFrictPhys_CohesionMoment()]),
    NewtonIntegrator(damping=0.05),
]
O.dt = dt
O.step()  # makes the cohesive bonds
random.seed(3)
for b in O.bodies:
    b.state.vel = (random.uniform(-1e-3, 1e-3), random.uniform(-1e-3, 1e-3), 0)
O.run(5, True)  # warm up
best = 1e300
for repeat in range(3):
    start = time.time()
    O.run(steps, True)
    best = min(best, time.time() - start)
bonds = sum(1 for i in O.interactions if i.isReal)
spheres = len(O.bodies)
print("yade %d %d %d %d %.4f %.4g %.4g %.4g %.4g" %
      (spheres, bonds, O.numThreads, steps, best, spheres * steps / best, bonds * steps / best, dt,
       utils.PWaveTimeStep()))
