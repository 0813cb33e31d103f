#!/usr/bin/python3
"""Write the static column's disks and box into a case made from the
sedimentation10k tutorial (validation/staticColumn/Allrun).

A hexagonal column of 40 rows of disks of r = 0.025 (20 and 19 disks
alternately, 780 in all) at rest on the floor of a box one row wide (the
sedimentation10k tutorial's disks, fluid and contact law), the disks 1e-3
of a diameter apart, 1e-4 above the floor and the side walls. Writes
constant/particles (the tutorial's particle list) and sets the box's
vertices and cell counts in system/blockMeshDict (cells of 0.025, the
tutorial's level 3: r/h = 1).

Usage: makeColumn.py CASE
"""
import math
import re
import sys

R, ROWS, GAP = 0.025, 40, 1e-4
HEIGHT = 3.0


def lattice():
    """Centres of the column's disks, row by row from the floor"""
    pitch = 2*R*1.001
    rise = pitch*math.sqrt(3)/2
    pts = []
    for k in range(ROWS):
        n = 20 if k % 2 == 0 else 19
        x0 = R + GAP + (0 if k % 2 == 0 else pitch/2)
        pts += [(x0 + pitch*i, R + GAP + k*rise, k) for i in range(n)]
    width = R + GAP + 19*pitch + R + GAP
    return pts, width


def main(case):
    pts, width = lattice()
    with open(case + '/constant/particles', 'w') as f:
        f.write('// makeColumn.py: %d disks, (x y z) radius\nparticles\n%d\n(\n'
                % (len(pts), len(pts)))
        for x, y, _ in pts:
            f.write('    (%.9g %.9g 0) %g\n' % (x, y, R))
        f.write(');\n')
    bm = case + '/system/blockMeshDict'
    s = open(bm).read()
    s, n = re.subn(r'vertices\s*\(.*?\);',
                   'vertices\n(\n    (0 0 -0.05) (%.9g 0 -0.05) (%.9g %g -0.05) (0 %g -0.05)\n'
                   '    (0 0  0.05) (%.9g 0  0.05) (%.9g %g  0.05) (0 %g  0.05)\n);'
                   % ((width, width, HEIGHT, HEIGHT)*2), s, flags=re.S)
    assert n == 1, 'vertices not found in ' + bm
    s, n = re.subn(r'level3 \{[^}]*\}', 'level3 { nx %d; ny %d; }'
                   % (round(width/0.025), round(HEIGHT/0.025)), s)
    assert n == 1, 'level3 not found in ' + bm
    open(bm, 'w').write(s)


if __name__ == '__main__':
    main(sys.argv[1])
