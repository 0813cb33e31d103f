#!/usr/bin/python3
"""Write system/blockMeshDict of the body-fitted oscillating-cylinder case.

Usage: makeMesh.py LEVEL [CASE]

The same box [-12, 12]^2 and cell size h = D/(12 2^(LEVEL - 1)) as the
fbmFoam tutorial (tutorials/fbmFoam/oscillatingCylinder), with the cylinder
(D = 1 at the origin) meshed: an O-grid of four blocks between the cylinder
and the square [-1, 1]^2 (48 cells per quarter at level 2, 19 radially,
graded 2.5 towards the cylinder, as the DFG 2D-1 body-fitted mesh of
validation/cylinderDFG2D-1 scaled by 10), uniform cells h in [-3, 3] x
[-2, 2] around it, and the fbmFoam tutorial's graded outer blocks. The
whole mesh moves with the cylinder (solidBody motion), so the fine cells
stay with it.
"""
import math
import sys

level = int(sys.argv[1])
case = sys.argv[2] if len(sys.argv) > 2 else "."

# Outer blocks: the fbmFoam tutorial's counts and expansion ratios
outer = {1: (21, 16.37, 22, 18.82), 2: (26, 32.92, 26, 32.92),
         3: (30, 57.58, 31, 66.21)}
nox, gx, noy, gy = outer[level]
perD = 12*2**(level - 1)            # cells per diameter
nC = 2*perD                         # cells per quarter of the cylinder
nR = round(0.4*nC)                  # radially
gR = 2.5
R = 0.5

xs = [-12, -3, -1, 1, 3, 12]
ys = [-12, -2, -1, 1, 2, 12]
nx = [nox, 2*perD, nC, 2*perD, nox]
ny = [noy, perD, nC, perD, noy]
grx = [1/gx, 1, 1, 1, gx]
gry = [1/gy, 1, 1, 1, gy]
z = [-0.05, 0.05]


def v(i, j, k):
    return k*40 + j*6 + i


def c(m, k):
    return k*40 + 36 + m


verts = []
for k in range(2):
    for j in range(6):
        for i in range(6):
            verts.append((xs[i], ys[j], z[k]))
    for a in (225, 315, 45, 135):
        verts.append((R*math.cos(math.radians(a)),
                      R*math.sin(math.radians(a)), z[k]))

blocks = []
front = []
for j in range(5):
    for i in range(5):
        if i == 2 and j == 2:
            continue
        q = [v(i, j, 0), v(i + 1, j, 0), v(i + 1, j + 1, 0), v(i, j + 1, 0)]
        blocks.append((q + [p + 40 for p in q], (nx[i], ny[j]),
                       (grx[i], gry[j])))
        front.append(q)
S = [v(2, 2, 0), v(3, 2, 0), v(3, 3, 0), v(2, 3, 0)]
C = [c(m, 0) for m in range(4)]
for m in range(4):
    q = [S[m], S[(m + 1) % 4], C[(m + 1) % 4], C[m]]
    blocks.append((q + [p + 40 for p in q], (nC, nR), (1, 1/gR)))
    front.append(q)

walls = []
for i in range(5):
    walls.append((v(i, 0, 0), v(i + 1, 0, 0), v(i + 1, 0, 1), v(i, 0, 1)))
    walls.append((v(i, 5, 0), v(i, 5, 1), v(i + 1, 5, 1), v(i + 1, 5, 0)))
for j in range(5):
    walls.append((v(0, j, 0), v(0, j, 1), v(0, j + 1, 1), v(0, j + 1, 0)))
    walls.append((v(5, j, 0), v(5, j + 1, 0), v(5, j + 1, 1), v(5, j, 1)))
cyl = [(C[m], C[m] + 40, C[(m + 1) % 4] + 40, C[(m + 1) % 4])
       for m in range(4)]

out = []
w = out.append
w("""/*--------------------------------*- C++ -*----------------------------------*\\
| =========                 |                                                 |
| \\\\      /  F ield         | OpenFOAM: The Open Source CFD Toolbox           |
|  \\\\    /   O peration     | Version:  v1912                                 |
|   \\\\  /    A nd           | Website:  www.openfoam.com                      |
|    \\\\/     M anipulation  |                                                 |
\\*---------------------------------------------------------------------------*/
FoamFile
{
    version     2.0;
    format      ascii;
    class       dictionary;
    location    "system";
    object      blockMeshDict;
}
// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //
""")
w("// Written by makeMesh.py %d (level %d): do not edit\n\nscale 1;\n\nvertices\n(\n"
  % (level, level))
for p in verts:
    w("    (%.12g %.12g %.12g)\n" % p)
w(");\n\nblocks\n(\n")
for q, n, g in blocks:
    w("    hex (%s) (%d %d 1) simpleGrading (%.10g %.10g 1)\n"
      % (" ".join(map(str, q)), n[0], n[1], g[0], g[1]))
w(");\n\nedges\n(\n")
mid = [(0, -R), (R, 0), (0, R), (-R, 0)]
for k in range(2):
    for m in range(4):
        w("    arc %d %d (%.12g %.12g %.12g)\n"
          % (c(m, k), c((m + 1) % 4, k), mid[m][0], mid[m][1], z[k]))
w(");\n\nboundary\n(\n")


def patch(name, kind, faces):
    w("    %s\n    {\n        type %s;\n        faces\n        (\n" % (name, kind))
    for f in faces:
        w("            (%s)\n" % " ".join(map(str, f)))
    w("        );\n    }\n")


patch("walls", "wall", walls)
patch("cylinder", "wall", cyl)
patch("frontAndBack", "empty",
      [tuple(reversed(q)) for q in front] + [tuple(p + 40 for p in q) for q in front])
w(");\n\n// ************************************************************************* //\n")
open(case + "/system/blockMeshDict", "w").write("".join(out))
