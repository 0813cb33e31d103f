#!/usr/bin/python3
"""Grade the settlingParticle tutorial's mesh across the channel.

Usage: gradeMesh.py CASE LEVEL RATIO

The channel (2 wide) in three blocks across: the strip 0.625 < x < 1.375
(3 d wide about the path x = 1 of the disk) at the level's cell size
h = 1/(24 2^(LEVEL - 3)), and beside it n cells growing geometrically from
about h at the strip to RATIO h at the side walls (n the count whose cell
next to the strip is nearest h; RATIO 1: uniform, the tutorial's own mesh
up to the block faces). Along the channel unchanged. Edits
CASE/system/blockMeshDict, which must be the tutorial's.
"""
import sys

case, level, ratio = sys.argv[1], int(sys.argv[2]), float(sys.argv[3])
f = case + "/system/blockMeshDict"
s = open(f).read()
h = 1.0/(24*2**(level - 3))
side = 0.625
nStrip = round(0.75/h)


def firstCell(n):
    """the cell next to the strip when n cells grow to ratio times it"""
    if n == 1 or ratio == 1:
        return side/n
    q = ratio**(1.0/(n - 1))
    return side*(q - 1)/(q**n - 1)


nSide = min(range(1, 4*round(side/h)), key=lambda n: abs(firstCell(n) - h))
edits = [
    ("    (0 0 -0.05) (2 0 -0.05) (2 6 -0.05) (0 6 -0.05)\n"
     "    (0 0  0.05) (2 0  0.05) (2 6  0.05) (0 6  0.05)",
     "    (0 0 -0.05) (0.625 0 -0.05) (1.375 0 -0.05) (2 0 -0.05)\n"
     "    (0 6 -0.05) (0.625 6 -0.05) (1.375 6 -0.05) (2 6 -0.05)\n"
     "    (0 0  0.05) (0.625 0  0.05) (1.375 0  0.05) (2 0  0.05)\n"
     "    (0 6  0.05) (0.625 6  0.05) (1.375 6  0.05) (2 6  0.05)"),
    ("    hex (0 1 2 3 4 5 6 7) ($nx $ny 1) simpleGrading (1 1 1)",
     "    hex (0 1 5 4 8 9 13 12) (%d $ny 1) simpleGrading (%.12g 1 1)\n"
     "    hex (1 2 6 5 9 10 14 13) (%d $ny 1) simpleGrading (1 1 1)\n"
     "    hex (2 3 7 6 10 11 15 14) (%d $ny 1) simpleGrading (%.12g 1 1)"
     % (nSide, 1/ratio, nStrip, nSide, ratio)),
    ("        faces ((0 4 7 3) (1 2 6 5) (0 1 5 4) (3 7 6 2));",
     "        faces ((0 8 12 4) (3 7 15 11) (0 1 9 8) (1 2 10 9) (2 3 11 10)\n"
     "               (4 12 13 5) (5 13 14 6) (6 14 15 7));"),
    ("        faces ((0 3 2 1) (4 5 6 7));",
     "        faces ((0 4 5 1) (1 5 6 2) (2 6 7 3) (8 9 13 12) (9 10 14 13)\n"
     "               (10 11 15 14));")]
for a, b in edits:
    if s.count(a) != 1:
        sys.exit("%s: not the tutorial's mesh (no '%s')" % (f, a.strip()[:50]))
    s = s.replace(a, b)
open(f, "w").write(s)
print("%s: %d + %d + %d cells across (h = %.5g, %.3g h at the side walls)"
      % (case, nSide, nStrip, nSide, h, ratio))
