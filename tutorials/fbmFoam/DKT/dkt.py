#!/usr/bin/python3
"""Drafting, kissing, tumbling: times and distances from the fbmBodies output.

Usage: ./dkt.py [CASE]   (default: this folder)

Reads postProcessing/fbmBodies/<start>/{lower,upper}.dat (columns Time Fx
Fy Fz Tx Ty Tz x y z Ux Uy Uz wx wy wz), writes dkt.csv (t, centres, gap)
and prints:
- kissing: the first time the surface gap falls below the repulsion range
  (1.5 h) and how long it stays below;
- the smallest gap and when;
- tumbling: the first time the trailing disk (upper at the start) is no
  longer above the leading one (its y below the other's);
- the positions at the end.
"""
import glob
import os
import re
import sys

case = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__))


def rows(name):
    out = {}
    for f in sorted(glob.glob(os.path.join(case, 'postProcessing/fbmBodies/*', name + '.dat')),
                    key=lambda p: float(p.split('/')[-2])):
        for line in open(f):
            if line.startswith('#'):
                continue
            v = [float(x) for x in line.split()]
            out[v[0]] = v
    return out


A, B = rows('lower'), rows('upper')
times = sorted(set(A) & set(B))
if not times:
    sys.exit('no fbmBodies output in ' + case)

params = open(os.path.join(case, 'system/caseParameters')).read()
level = int(re.search(r'^level\s+(\d+);', params, re.M).group(1))
h = 2.0/(24*2**(level - 2))
R = 0.1
rng = 1.5*h

csv = open(os.path.join(case, 'dkt.csv'), 'w')
csv.write('t,x_lower,y_lower,x_upper,y_upper,gap\n')
kiss = None
kissEnd = None
tumble = None
gmin, tmin = 1e30, None
for t in times:
    a, b = A[t], B[t]
    d = ((a[7] - b[7])**2 + (a[8] - b[8])**2)**0.5
    gap = d - 2*R
    csv.write('%g,%.6f,%.6f,%.6f,%.6f,%.6f\n' % (t, a[7], a[8], b[7], b[8], gap))
    if gap < gmin:
        gmin, tmin = gap, t
    if kiss is None and gap < rng:
        kiss = t
    if kiss is not None and kissEnd is None and gap >= rng:
        kissEnd = t
    if tumble is None and b[8] <= a[8]:
        tumble = t

print('level %d: h = %.5f, R/h = %.1f, range 1.5 h = %.5f' % (level, h, R/h, rng))
print('kissing (gap < range): from t = %s to t = %s'
      % (kiss if kiss is None else '%.3f' % kiss,
         kissEnd if kissEnd is None else '%.3f' % kissEnd))
print('smallest gap %.5f (%.2f h) at t = %.3f' % (gmin, gmin/h, tmin))
print('tumbling (trailing disk level with or below the leading one): t = %s'
      % (tumble if tumble is None else '%.3f' % tumble))
t = times[-1]
print('t = %.3f: lower (%.4f, %.4f), upper (%.4f, %.4f)'
      % (t, A[t][7], A[t][8], B[t][7], B[t][8]))
