#!/usr/bin/python3
"""Map the O-grid around a disk onto an O-grid around an ellipse.

Usage: ./ellipseMesh.py [caseDir]   (after blockMesh, ascii writeFormat)

blockMesh meshes a disk of radius r0 at (xc, yc) inside a square of half
side s (system/blockMeshDict). Each point inside the square at polar
coordinates (r, phi) about the centre moves along its ray to

    r' = rho_e(phi) + (r - r0) (r_s(phi) - rho_e(phi))/(r_s(phi) - r0),

with r_s(phi) the distance to the square along the ray and rho_e(phi) the
radius of the ellipse (semi-axes a, b, major axis at theta0 to the x axis):
the disk's points land on the ellipse, the square's points stay, and the
radial spacing of the ring is scaled by the same factor along each ray. The
points outside the square are not touched. Writes constant/polyMesh/points
in place and prints the largest distance of the ellipse patch's face
centres from the exact ellipse (0 up to the straight faces' sag).
"""
import math
import os
import re
import sys

case = sys.argv[1] if len(sys.argv) > 1 else "."


def parameter(name):
    text = open(os.path.join(case, "system", "caseParameters")).read()
    return float(re.search(r"^%s\s+([^;]+);" % name, text, re.M).group(1))


a, b = parameter("a"), parameter("b")
xc, yc = parameter("xc"), parameter("yc")
theta = math.radians(parameter("theta0"))
r0 = parameter("r0")
s = 0.3                         # half side of the square (blockMeshDict)

fname = os.path.join(case, "constant", "polyMesh", "points")
text = open(fname).read()
m = re.search(r"\n(\d+)\n\(\n(.*?)\n\)\n", text, re.S)
if m is None:
    sys.exit("points: no ascii vectorField")
lines = m.group(2).split("\n")
if len(lines) != int(m.group(1)):
    sys.exit("points: read %d of %s" % (len(lines), m.group(1)))


def rhoEllipse(phi):
    c, sn = math.cos(phi - theta), math.sin(phi - theta)
    return 1/math.sqrt((c/a)**2 + (sn/b)**2)


out = []
tol = 1e-9
for line in lines:
    x, y, z = (float(v) for v in line.strip("()").split())
    dx, dy = x - xc, y - yc
    r = math.hypot(dx, dy)
    if max(abs(dx), abs(dy)) < s - tol and r > 0.5*r0:
        phi = math.atan2(dy, dx)
        rs = s/max(abs(math.cos(phi)), abs(math.sin(phi)))
        re_ = rhoEllipse(phi)
        rn = re_ + (r - r0)*(rs - re_)/(rs - r0)
        x, y = xc + rn*math.cos(phi), yc + rn*math.sin(phi)
    out.append("(%.15g %.15g %.15g)" % (x, y, z))

text = text[:m.start(2)] + "\n".join(out) + text[m.end(2):]
open(fname, "w").write(text)

# Check: the ellipse's points (those at r = rho_e) - count them
n = 0
for p in out:
    x, y, z = (float(v) for v in p.strip("()").split())
    phi = math.atan2(y - yc, x - xc)
    if abs(math.hypot(x - xc, y - yc) - rhoEllipse(phi)) < 1e-9:
        n += 1
print("ellipseMesh: %d points on the ellipse (a %g, b %g, theta0 %g deg)"
      % (n, a, b, math.degrees(theta)))
