#!/usr/bin/python3
"""Build the two cases of the moving-body check from the settlingParticle
tutorial (channel 2 wide, disk R = 0.125, nu 0.1), in a 2 x 8 box:

  bodyFrame: the disk held at (1, 2.5); fluid enters at the bottom with the
             speed V, the side walls move with V, outlet at the top: the
             steady flow past a disk falling at V in an endless channel.
  moving:    the same disk moving down at the constant (prescribed) speed V
             from (1, 7) through fluid at rest in a closed box.

The drag of the two must agree (Galilean invariance); the difference is the
error of the moving interface. Usage: makeCases.py TUTORIAL DEST V
"""
import os
import shutil
import subprocess
import sys

BIN = os.path.join(os.path.dirname(os.path.abspath(__file__)),
                   "..", "..", "..", "bin")
sys.path.insert(0, BIN)
from fbmCaseEdit import edit, bodyFrameInflow  # noqa: E402  (bin/fbmCaseEdit.py)

tutorial, dest, V = sys.argv[1], sys.argv[2], sys.argv[3]


for name in ("bodyFrame", "moving"):
    case = "%s/%s" % (dest, name)
    shutil.rmtree(case, ignore_errors=True)
    shutil.copytree(tutorial, case)
    for f in ("Allrun", "Allclean", "README.md"):
        os.remove("%s/%s" % (case, f))
    # Box 2 x 8 with the same cell size as the tutorial's levels
    edit(case + "/system/blockMeshDict", [
        ("(2 6 -0.05) (0 6 -0.05)", "(2 8 -0.05) (0 8 -0.05)"),
        ("(2 6  0.05) (0 6  0.05)", "(2 8  0.05) (0 8  0.05)")])
    edit(case + "/system/blockMeshDict", [
        (r"level(\d) \{ nx (\d+); *ny (\d+); *\}",
         lambda m: "level%s { nx %s; ny %d; }"
         % (m.group(1), m.group(2), int(m.group(3))*8//6))], regex=True)
    edit(case + "/system/controlDict", [
        (r"\nendTime .*;", "\nendTime         %s;"
         % ("2" if name == "bodyFrame" else "0.6")),
        (r"\nwriteInterval .*;", "\nwriteInterval   10;")], regex=True)
    edit(case + "/constant/fbmProperties", [
        ("translate   yes;", "translate   no;"),
        ("rotate      yes;", "rotate      no;")])
    # A held or prescribed body: no coupling acts on it. The explicit
    # coupling's settings (no PIMPLE consistent, which the tutorial's
    # coupling semiImplicit needs since 2026-12-05): the fluid step of the
    # committed runs (results.csv)
    subprocess.check_call([os.path.join(BIN, "fbmSetCoupling"), case,
                           "explicit"])

    if name == "moving":
        edit(case + "/constant/fbmProperties", [
            ("centre      (1 4 0);", "centre      (1 7 0);"),
            ("U           (0 0 0);", "U           (0 -%s 0);" % V)])
        continue

    edit(case + "/constant/fbmProperties", [
        ("centre      (1 4 0);", "centre      (1 2.5 0);")])
    edit(case + "/system/controlDict", [
        (r"\nmaxCo .*;", "\nmaxCo           1;"),
        (r"\nmaxDeltaT .*;", "\nmaxDeltaT       1;")], regex=True)
    edit(case + "/system/blockMeshDict", [
        ("faces ((0 4 7 3) (1 2 6 5) (0 1 5 4) (3 7 6 2));",
         "faces ((0 4 7 3) (1 2 6 5));\n    }\n    inlet\n    {\n"
         "        type patch;\n        faces ((0 1 5 4));\n    }\n"
         "    outlet\n    {\n        type patch;\n"
         "        faces ((3 7 6 2));")])
    bodyFrameInflow(case, V)
