#!/usr/bin/python3
"""The static column's runs against statics (validation/staticColumn).

For every run in RUNS_DIR (Allrun) and every written time, from the cloud
(positions, U, F: the hydrodynamic force) and the contact law of the
case's constant/fbmProperties (singhRepulsion, rangePlusLinear, its
constants recomputed here, dashpot left out: it acts only while the disks
move):
- the largest speed;
- the floor's load (the wall law on the bottom row) over the column's
  submerged weight N |W|: 1 for a column at rest in a fluid at rest;
- the fluid's share, the sum of the hydrodynamic forces' vertical
  components over N |W| (0 at rest);
- the load each row interface k carries, the vertical pair forces between
  rows k and k+1, over the submerged weight of the rows above: the largest
  departure from 1 over the 39 interfaces;
- the largest pair overlap (% of r), and what statics gives for it in a
  perfect hexagonal column: the submerged weight of the rows above the
  bottom one shared by the 38 contacts below row 1, at 30 degrees from
  the vertical, the law inverted.
Writes history.csv (run, time), results.csv (run, last time, CPU),
column.png. Exits 1 if a run has no cloud or did not end.

Usage: analyse.py RUNS_DIR [OUT_DIR]   (OUT_DIR: where the csv files and
the chart go; default this folder)
"""
import csv
import math
import os
import re
import sys

import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, '..', '..', 'bin'))
import fbmOutput                                            # noqa: E402
sys.path.insert(0, here)
import makeColumn                                           # noqa: E402

ORDER = ['semiImplicit', 'rigidProjection', 'rigidProjection-relax1',
         'rigidProjection-noProject']
DEPTH = 0.1                     # the tutorial's mesh depth (2D)


def number(text, key):
    m = re.search(r'^\s*' + key + r'\s+([0-9.eE+-]+)\s*;', text, re.M)
    if not m:
        raise ValueError('no %s' % key)
    return float(m.group(1))


class Law:
    """The rangePlusLinear repulsion per unit depth times DEPTH"""
    def __init__(self, case):
        text = open(case + '/constant/fbmProperties').read()
        assert re.search(r'overlapForce\s+rangePlusLinear', text)
        self.rng = number(text, 'range')
        self.eps = number(text, 'epsP')
        self.epsO = number(text, 'epsPOverlap')
        self.epsW = number(text, 'epsW')
        self.epsWO = number(text, 'epsWOverlap')
        self.rhoF = number(text, 'rhoFluid')
        self.rho = number(text, 'rho')
        g = open(case + '/constant/g').read()
        self.g = abs(float(re.search(r'value\s+\(\s*\S+\s+(\S+)', g).group(1)))

    def pair(self, s, D, eps, epsO):
        if D >= s + self.rng:
            return 0.0
        return D*DEPTH*((s + self.rng - D)**2/eps + max(0.0, s - D)/epsO)

    def overlapFor(self, f, s):
        lo, hi = s - 0.5*s, s + self.rng
        for _ in range(200):
            mid = 0.5*(lo + hi)
            if self.pair(s, mid, self.eps, self.epsO) > f:
                lo = mid
            else:
                hi = mid
        return s - 0.5*(lo + hi)


def analyse(case, name):
    law = Law(case)
    pts, width = makeColumn.lattice()
    row = np.array([k for _, _, k in pts])
    nRows = row.max() + 1
    r = makeColumn.R
    s = 2*r
    W = (law.rho - law.rhoF)*math.pi*r*r*DEPTH*law.g
    n = len(pts)
    rows = []
    for t in fbmOutput.cloudTimes(case):
        if float(t) == 0:
            continue
        c = fbmOutput.readCloud(case, t, fields=('U', 'F', 'id'))
        X, U, F = c['positions'], c['U'], c['F']
        assert len(X) == n
        floor = sum(law.pair(s, 2*y, law.epsW, law.epsWO) for y in X[:, 1])
        load = np.zeros(nRows)           # load[k]: across rows k, k+1
        largest = 0.0
        for i in range(n):
            for j in range(i + 1, n):
                d = X[j, :2] - X[i, :2]
                D = math.hypot(*d)
                if D >= s + law.rng:
                    continue
                largest = max(largest, (s - D)/r)
                lower, upper = (i, j) if X[j, 1] > X[i, 1] else (j, i)
                if row[upper] == row[lower] + 1:
                    load[row[lower]] += law.pair(s, D, law.eps, law.epsO) \
                        * abs(d[1])/D
        above = np.array([(row > k).sum() for k in range(nRows - 1)])
        interface = load[:nRows - 1]/(above*W)
        bottom = above[0]*W/(sum(1 for k in row if k == 1)*2*math.cos(math.pi/6))
        rows.append(dict(
            run=name, t=float(t),
            max_speed=float(np.hypot(U[:, 0], U[:, 1]).max()),
            floor_load=floor/(n*W),
            fluid_share=float(F[:, 1].sum()/(n*W)),
            interface_error=float(np.abs(interface - 1).max()),
            overlap_r=largest,
            static_overlap_r=law.overlapFor(bottom, s)/r))
    return rows


def main(runsDir, out=here):
    names = [d for d in ORDER if os.path.isdir(os.path.join(runsDir, d))]
    history, results, bad = [], [], False
    for name in names:
        case = os.path.join(runsDir, name)
        rows = analyse(case, name)
        log = open(case + '/log.fbmFoam').read()
        ended = re.search(r'^End\s*$', log, re.M) is not None
        if not rows or not ended:
            print('%s: %s' % (name, 'no cloud' if not rows else 'did not end'))
            bad = True
            continue
        history += rows
        last = dict(rows[-1])
        last['cpu_s'] = fbmOutput.cpuTime(case + '/log.fbmFoam')
        results.append(last)
        print('%-26s t %.2f: speed %.3g cm/s, floor %.4f N|W|, fluid %+.4f,'
              ' interfaces within %.4f, overlap %.2f %% r (statics %.2f %%),'
              ' %.0f s' % (name, last['t'], last['max_speed'],
                          last['floor_load'], last['fluid_share'],
                          last['interface_error'], 100*last['overlap_r'],
                          100*last['static_overlap_r'], last['cpu_s']))
    keys = ['run', 't', 'max_speed', 'floor_load', 'fluid_share',
            'interface_error', 'overlap_r', 'static_overlap_r']
    for path, data, cols in (('history.csv', history, keys),
                             ('results.csv', results, keys + ['cpu_s'])):
        with open(os.path.join(out, path), 'w', newline='') as fh:
            w = csv.DictWriter(fh, fieldnames=cols, lineterminator='\n')
            w.writeheader()
            for row in data:
                w.writerow({k: ('%.6g' % v if isinstance(v, float) else v)
                            for k, v in row.items()})
    plot(history, names, out)
    return 1 if bad else 0


def plot(history, names, out):
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(1, 3, figsize=(13, 3.8))
    for name in names:
        h = [r for r in history if r['run'] == name]
        t = [r['t'] for r in h]
        ax[0].plot(t, [r['floor_load'] for r in h], 'o-', label=name)
        ax[1].semilogy(t, [max(r['max_speed'], 1e-6) for r in h], 'o-')
        ax[2].plot(t, [100*r['overlap_r'] for r in h], 'o-')
    if history:
        ax[2].axhline(100*history[-1]['static_overlap_r'], color='k', ls=':',
                      label='statics')
    ax[0].axhline(1, color='k', ls=':')
    ax[0].set_ylabel('floor load / submerged weight')
    ax[1].set_ylabel('largest speed [cm/s]')
    ax[2].set_ylabel('largest pair overlap [% of r]')
    for a in ax:
        a.set_xlabel('t [s]')
    ax[0].legend(fontsize=7)
    ax[2].legend(fontsize=7)
    fig.suptitle('A column of 780 disks at rest on the floor (40 rows, r/h = 1)')
    fig.tight_layout()
    fig.savefig(os.path.join(out, 'column.png'), dpi=110)


if __name__ == '__main__':
    sys.exit(main(*sys.argv[1:3]))
