#!/usr/bin/python3
"""Make the mesh of the latest time the new reference of the mesh motion.

Usage: ./reReference.py [caseDir [patch sizeKey]]     (ascii writeFormat)
  patch:   the body's patch (default disk)
  sizeKey: the caseParameters entry of the body's half height for the gap
           (default radius; the settling ellipse of
           validation/ellipseSettling/bodyFitted uses ellipse a)

displacementLaplacian moves the points to points0 + pointDisplacement, with
pointDisplacement solved from the body's displacement since points0; the
sixDoFRigidBodyDisplacement condition gives the body's points as the rigid
motion of its initialPoints since (centreOfMass, initialOrientation). At the
latest time T this script, with the solver stopped:

- writes T/polyMesh/points0 = T/polyMesh/points (the motion solver reads
  points0 from the latest time that has one);
- in T/pointDisplacement sets initialPoints to the body's current points
  (initialPoints + value), centreOfMass (the initial one) and
  initialOrientation to the current centreOfRotation and orientation, the
  constraints' centreOfRotation to the current one too, and every
  displacement to 0;
- in T/cellDisplacement sets every displacement to 0.

The motion state (velocity, acceleration, angular momentum, torque) is
untouched, so the body goes on as before; only the mesh solution restarts
from the current, deformed mesh. Prints the time, the body's centre x y, its
gap to the bottom wall (y - R, R the sizeKey entry) and this script's CPU
time [s].
"""
import os
import re
import sys
import time

case = sys.argv[1] if len(sys.argv) > 1 else "."
patch = sys.argv[2] if len(sys.argv) > 2 else "disk"
sizeKey = sys.argv[3] if len(sys.argv) > 3 else "radius"


def latestTime():
    times = []
    for d in os.listdir(case):
        try:
            times.append((float(d), d))
        except ValueError:
            pass
    return max(times)[1]


def vectors(text):
    return [[float(v) for v in x.split()]
            for x in re.findall(r"\(([^()]*)\)", text)]


def vectorList(name, block):
    """The nonuniform List<vector> entry `name` of a dictionary block."""
    m = re.search(name + r"\s+nonuniform\s+List<vector>\s*(\d+)\s*\((.*?)\n\)\s*;",
                  block, re.S)
    if m is None:
        sys.exit(f"{name}: no nonuniform List<vector> (ascii writeFormat?)")
    vals = vectors(m.group(2))
    if len(vals) != int(m.group(1)):
        sys.exit(f"{name}: read {len(vals)} of {m.group(1)} vectors")
    return m, vals


def formatList(vals):
    return "nonuniform List<vector> %d\n(\n%s\n)\n;" % (
        len(vals),
        "\n".join("(%.15g %.15g %.15g)" % tuple(v) for v in vals))


def setEntry(block, key, value):
    new, n = re.subn(r"(\n\s*%s\s+)[^;]*;" % key,
                     lambda m: m.group(1) + value + ";", block, count=1)
    if n != 1:
        sys.exit(f"entry {key} not found")
    return new


def zeroDisplacements(text):
    """internalField and every patch value of a vector field set to 0."""
    text = re.sub(r"(internalField\s+)(nonuniform\s+List<vector>\s*\d+\s*"
                  r"\(.*?\n\)\s*|uniform\s*\([^()]*\)\s*);",
                  r"\1uniform (0 0 0);", text, count=1, flags=re.S)
    return re.sub(r"(\n\s*value\s+)(nonuniform\s+List<vector>\s*\d+\s*"
                  r"\(.*?\n\)\s*|uniform\s*\([^()]*\)\s*);",
                  r"\1uniform (0 0 0);", text, flags=re.S)


T = latestTime()
tdir = os.path.join(case, T)

# points0 = current points
with open(os.path.join(tdir, "polyMesh", "points")) as f:
    points = f.read()
points0, n = re.subn(r"(\n\s*object\s+)points;", r"\1points0;", points, 1)
if n != 1:
    sys.exit("points: no object entry")
with open(os.path.join(tdir, "polyMesh", "points0"), "w") as f:
    f.write(points0)

# pointDisplacement: the body's reference is its current position
fname = os.path.join(tdir, "pointDisplacement")
text = open(fname).read()
m = re.search(r"\n    " + re.escape(patch) + r"\n    \{\n(.*?)\n    \}\n",
              text, re.S)
if m is None:
    sys.exit("pointDisplacement: no %s patch" % patch)
disk = m.group(1)
mInit, initial = vectorList("initialPoints", disk)
mValue, value = vectorList("value", disk)
current = [[a + b for a, b in zip(p, d)] for p, d in zip(initial, value)]
centre = re.search(r"\n\s*centreOfRotation\s*\(([^()]*)\)\s*;", disk).group(1)
orientation = re.search(r"\n\s*orientation\s*\(([^()]*)\)\s*;", disk).group(1)
disk = disk.replace(mInit.group(0), "initialPoints   " + formatList(current))
disk = setEntry(disk, "centreOfMass", "(" + centre.strip() + ")")
# The constraints carry their own centreOfRotation (written as the initial
# one), which would override the body's: all to the current centre
disk = re.sub(r"(\n\s*centreOfRotation\s*)\([^()]*\)\s*;",
              lambda m: m.group(1) + "(" + centre.strip() + ");", disk)
disk = setEntry(disk, "initialOrientation", "(" + orientation.strip() + ")")
text = text[:m.start(1)] + disk + text[m.end(1):]
text = zeroDisplacements(text)
open(fname, "w").write(text)

# cellDisplacement: zero (it is solved again at the first step)
fname = os.path.join(tdir, "cellDisplacement")
if os.path.exists(fname):
    text = zeroDisplacements(open(fname).read())
    open(fname, "w").write(text)

x, y, z = (float(v) for v in centre.split())
R = float(re.search(r"^" + re.escape(sizeKey) + r"\s+([^;]+);", open(
    os.path.join(case, "system", "caseParameters")).read(), re.M).group(1))
print(f"{T} {x:.9g} {y:.9g} {y - R:.9g} {time.process_time():.2f}")
