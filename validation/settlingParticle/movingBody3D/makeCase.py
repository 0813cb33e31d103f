#!/usr/bin/python3
"""Build one case of the 3D moving-body check from the settlingSphere
tutorial (sphere d = 0.1, rho_s 1.5, nu 0.1, g 980, linearProfile forcing,
momentumExchange force), in a box W x L x W (x, y, z; y up) of uniform cubes
h = R/(R/h):

  bodyFrame: the sphere held on the axis at y = YB; fluid enters at the
             bottom with the speed V, the four side walls move with V,
             outlet at the top: the steady flow past a sphere falling at V
             in an endless square duct.
  moving:    the same sphere moving down the axis at the constant
             (prescribed) speed V from y = YM (translate no, U (0 -V 0))
             through fluid at rest in the closed box.

Both use the same mesh and numerics: one PIMPLE outer corrector, 2 PISO
correctors, `minIter 10` in the U solver, Euler, the time step fixed at
dt (body Courant number V dt/h); predictor 'extrapolated'
(`extrapolatePredictor yes`, the settlingParticle tutorial's settings),
'extrapolatedFlux' (the same with `extrapolatePressure no`: the flux
extrapolated, the pressure lagged) or
'lagged' (`extrapolatePredictor no`, minIter kept). The body frame's step
is free (its flow is steady): maxCo MAXCO (default 1), DT the first step.

Usage: makeCase.py TUTORIAL CASE KIND R/h V DT ENDTIME PREDICTOR [MAXCO]
"""
import os
import shutil
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "..", "bin"))
from fbmCaseEdit import edit, bodyFrameInflow  # noqa: E402  (bin/fbmCaseEdit.py)

W, L = 0.4, 1.2       # the box; d/W = 0.25
YB = 0.4              # the body frame's sphere: 0.35 below it, 0.75 above
YM = 1.0              # the moving sphere's start: 0.15 below the lid
R = 0.05

tutorial, case, kind, RH, V, dt, endTime, predictor = sys.argv[1:9]
maxCo = sys.argv[9] if len(sys.argv) > 9 else "1"
RH = float(RH)
if kind not in ("bodyFrame", "moving"):
    sys.exit("makeCase.py: KIND is bodyFrame or moving")
if predictor not in ("extrapolated", "extrapolatedFlux", "lagged"):
    sys.exit("makeCase.py: PREDICTOR is extrapolated, extrapolatedFlux or lagged")

h = R/RH
nxz, ny = round(W/h), round(L/h)
if abs(nxz*h - W) > 1e-9 or abs(ny*h - L) > 1e-9:
    sys.exit("makeCase.py: the box is not a whole number of cells at R/h %g" % RH)


shutil.rmtree(case, ignore_errors=True)
shutil.copytree(tutorial, case)
for f in ("Allrun", "Allclean", "README.md", "terminalVelocity.py"):
    os.remove("%s/%s" % (case, f))

edit(case + "/system/blockMeshDict", [
    ("    (0 0 0) (0.5 0 0) (0.5 1 0) (0 1 0)\n"
     "    (0 0 0.5) (0.5 0 0.5) (0.5 1 0.5) (0 1 0.5)",
     "    (0 0 0) (%g 0 0) (%g %g 0) (0 %g 0)\n"
     "    (0 0 %g) (%g 0 %g) (%g %g %g) (0 %g %g)"
     % (W, W, L, L, W, W, W, W, L, W, L, W)),
    ("(40 80 40)", "(%d %d %d)" % (nxz, ny, nxz))])
edit(case + "/system/controlDict", [
    (r"\nendTime .*;", "\nendTime         %s;" % endTime),
    (r"\ndeltaT .*;", "\ndeltaT          %s;" % dt),
    (r"\nwriteInterval .*;", "\nwriteInterval   10;")], regex=True)
edit(case + "/constant/fbmProperties", [
    ("translate   yes;", "translate   no;"),
    ("rotate      yes;", "rotate      no;")])
# The tutorial's predictor taken out (it extrapolates the flux since
# 2026-12-03); PREDICTOR puts back the one wanted
edit(case + "/system/fvSolution", [
    (r"\n *(extrapolatePredictor|extrapolatePressure|minIter) .*;", "")],
    regex=True)
edit(case + "/system/fvSolution", [
    ("        relTol          0;\n    }\n}",
     "        relTol          0;\n        minIter         10;\n    }\n}"),
    ("    nOuterCorrectors    1;\n",
     "    nOuterCorrectors    1;\n    extrapolatePredictor %s;\n%s"
     % ("no" if predictor == "lagged" else "yes",
        "    extrapolatePressure %s;\n"
        % ("no" if predictor == "extrapolatedFlux" else "yes")
        if predictor != "lagged" else ""))])

if kind == "moving":
    # The step fixed: body Courant number V dt/h
    edit(case + "/system/controlDict", [
        (r"\nadjustTimeStep .*;", "\nadjustTimeStep  no;")], regex=True)
    edit(case + "/constant/fbmProperties", [
        ("centre      (0.25 0.85 0.25);",
         "centre      (%g %g %g);" % (W/2, YM, W/2)),
        ("U           (0 0 0);", "U           (0 -%s 0);" % V)])
    sys.exit(0)

edit(case + "/constant/fbmProperties", [
    ("centre      (0.25 0.85 0.25);", "centre      (%g %g %g);" % (W/2, YB, W/2))])
edit(case + "/system/controlDict", [
    (r"\nmaxCo .*;", "\nmaxCo           %s;" % maxCo),
    (r"\nmaxDeltaT .*;", "\nmaxDeltaT       1;")], regex=True)
edit(case + "/system/blockMeshDict", [
    ("            (0 4 7 3) (1 2 6 5) (0 1 5 4) (3 7 6 2) (0 3 2 1) (4 5 6 7)",
     "            (0 4 7 3) (1 2 6 5) (0 3 2 1) (4 5 6 7)\n"
     "        );\n    }\n    inlet\n    {\n        type patch;\n"
     "        faces ((0 1 5 4));\n    }\n    outlet\n    {\n"
     "        type patch;\n        faces\n        (\n"
     "            (3 7 6 2)")])
bodyFrameInflow(case, V)
