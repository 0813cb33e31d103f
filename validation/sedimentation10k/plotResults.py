#!/usr/bin/python3
"""Snapshots, mean height and largest overlap of a sedimentation10k case.

Usage: plotResults.py [-o DIR] [--every DT] [--dpi DPI] CASE

CASE is a run of tutorials/fbmFoam/sedimentation10k (./Allrun makes
runs/L<level>; any other case folder of the scene, serial, decomposed or
reconstructed, continued or not, works too). Reads

    postProcessing/fbmBodies/*/summary.dat   joined over restarts (columns
                                   Time N maxSpeed kineticEnergy Xx Xy Xz
                                   minPairGap minWallGap)
    <time>/lagrangian/fbmBodies/   the cloud at the write times (positions,
                                   d, U), or processor*/<time>/... when the
                                   case folder has none
    constant/particles             the start (t = 0, at rest) when no cloud
                                   was written at 0 (fbmSetParticles)
    system/caseParameters, log.blockMesh, log.fbmFoam*  level, cavity,
                                   cells, CPU time (the last ExecutionTime
                                   of each log.fbmFoam* added up: the
                                   parts of a continued run)

and writes into DIR (default: the folder of this script)

    snapshots.png    panels at t = 0, DT, 2 DT, ... (DT = 1 by default) up
                     to the last written time: the disks as circles of
                     their size coloured by speed |U| (one colour scale),
                     DPI 150 by default, stored with a 256-colour palette
    meanHeight.csv   t, mean_y (mean centre height Xy), max_speed (largest
                     |U| + |omega| R), min_pair_gap, min_wall_gap (over the
                     collision sub-steps; empty when none within reach),
                     every time step
    meanHeight.png   mean height, largest speed and the smallest gaps (as
                     fractions of the radius r) against t
    results.csv      one row per case (replaced when the case is done
                     again): case (its real path), level, cells, N, r,
                     t_end, mean_y_start, mean_y_end, max_speed, t_max_speed,
                     pair_overlap_r and t_pair, wall_overlap_r and t_wall
                     (largest overlap over the run as a fraction of r: -gap/r,
                     0 when none), overlap_r (the larger of the two),
                     cpu_s, status (the run's exit status from exitStatus;
                     'none' without)

and prints the largest overlap, and a warning when the run's exitStatus is
not 0 (./Allrun's exit status says whether its run failed). Exit status 1
when the case has no summary.dat or nothing to draw.
Run it with Debian's python3 (/usr/bin/python3, python3-matplotlib).
"""

import argparse
import csv
import glob
import math
import os
import sys

import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, '..', '..', 'bin'))
import fbmOutput  # noqa: E402

import matplotlib  # noqa: E402
matplotlib.use('Agg')
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import EllipseCollection  # noqa: E402

COLUMNS = ['case', 'level', 'cells', 'N', 'r', 't_end', 'mean_y_start',
           'mean_y_end', 'max_speed', 't_max_speed', 'pair_overlap_r',
           't_pair', 'wall_overlap_r', 't_wall', 'overlap_r', 'cpu_s',
           'status']


def fmt(v):
    if v is None:
        return ''
    if isinstance(v, (float, np.floating)):
        return '%.6g' % v
    return str(v)


def snapshotFrames(case, every):
    """[(t, positions, d, speed)] at t = 0, every, 2 every, ...

    The cloud time nearest to each multiple of every (within every/4);
    t = 0 from constant/particles when no cloud was written at 0.
    """
    names = fbmOutput.cloudTimes(case)
    values = np.array([float(n) for n in names])
    last = values.max() if len(values) else 0.0
    frames = []
    for k in range(int(math.floor(last/every + 1e-9)) + 1):
        target = k*every
        if len(values):
            i = np.argmin(abs(values - target))
            if abs(values[i] - target) <= 0.25*every:
                c = fbmOutput.readCloud(case, names[i], ('d', 'U'))
                speed = np.sqrt((c['U']**2).sum(axis=1))
                frames.append((values[i], c['positions'], c['d'], speed))
                continue
        start = os.path.join(case, 'constant', 'particles')
        if k == 0 and os.path.isfile(start):
            X, r = fbmOutput.readParticleList(start)
            frames.append((0.0, X, 2*r, np.zeros(len(r))))
    return frames


def plotSnapshots(frames, box, title, path, dpi):
    n = len(frames)
    ncols = min(8, n)
    nrows = int(math.ceil(n/float(ncols)))
    (x0, y0, _), (x1, y1, _) = box
    w = 1.9
    hgt = w*(y1 - y0)/(x1 - x0)
    fig, axes = plt.subplots(nrows, ncols, figsize=(w*ncols + 1.2,
                                                    (hgt + 0.35)*nrows + 0.6),
                             squeeze=False)
    vmax = max([f[3].max() for f in frames] + [1e-12])
    for ax in axes.flat:
        ax.set_axis_off()
    for ax, (t, X, d, speed) in zip(axes.flat, frames):
        coll = EllipseCollection(d, d, np.zeros(len(d)), units='xy',
                                 offsets=X[:, :2], transOffset=ax.transData,
                                 cmap='viridis', linewidths=0)
        coll.set_array(speed)
        coll.set_clim(0, vmax)
        ax.add_collection(coll)
        ax.set_xlim(x0, x1)
        ax.set_ylim(y0, y1)
        ax.set_aspect('equal')
        ax.set_axis_on()
        ax.set_xticks([])
        ax.set_yticks([])
        ax.set_title('t = %g' % t, fontsize=9)
    fig.suptitle(title, fontsize=10)
    fig.subplots_adjust(left=0.02, right=0.9, bottom=0.02, top=0.9,
                        wspace=0.08, hspace=0.25)
    cax = fig.add_axes([0.92, 0.1, 0.015, 0.75])
    sm = plt.cm.ScalarMappable(cmap='viridis',
                               norm=plt.Normalize(0, vmax))
    fig.colorbar(sm, cax=cax, label='|U| [cm/s]')
    fig.savefig(path, dpi=dpi)
    plt.close(fig)
    # 16 panels of 10,000 disks: a 256-colour palette makes the file about
    # 3 times smaller (PIL, python3-pil; skipped without it)
    try:
        from PIL import Image
    except ImportError:
        return
    Image.open(path).convert('RGB').quantize(256).save(path, optimize=True)


def plotMeanHeight(s, r, title, path):
    t = s['Time']
    fig, ax = plt.subplots(3, 1, figsize=(8, 9), sharex=True)
    ax[0].plot(t, s['Xy'])
    ax[0].set_ylabel('mean centre height [cm]')
    ax[1].plot(t, s['maxSpeed'])
    ax[1].set_ylabel('largest |U| + |omega| r [cm/s]')
    for key, lab in (('minPairGap', 'pairs'), ('minWallGap', 'walls')):
        g = np.where(s[key] < 0.1*fbmOutput.GREAT, s[key], np.nan)
        ax[2].plot(t, g/r, label=lab)
    ax[2].axhline(0, color='k', lw=0.8)
    ax[2].set_ylabel('smallest gap / r')
    ax[2].set_xlabel('t [s]')
    ax[2].legend(fontsize=8)
    ax[0].set_title(title)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('case')
    ap.add_argument('-o', '--output', default=here,
                    help='folder for the charts and CSV (default: %(default)s)')
    ap.add_argument('--every', type=float, default=1.0,
                    help='time between snapshot panels (default: 1)')
    ap.add_argument('--dpi', type=float, default=150,
                    help='resolution of snapshots.png (default: 150)')
    args = ap.parse_args()
    case = args.case
    out = args.output
    os.makedirs(out, exist_ok=True)

    s = fbmOutput.summary(case)
    if not s:
        print('%s: no postProcessing/fbmBodies/*/summary.dat (see the log.*'
              ' there)' % case)
        return 1

    row = {'case': os.path.realpath(case)}
    try:
        row['status'] = open(os.path.join(case, 'exitStatus')).read().strip()
    except OSError:
        row['status'] = 'none'
    params = os.path.join(case, 'system', 'caseParameters')
    if os.path.isfile(params):
        row['level'] = fbmOutput.dictEntry(params, 'level')
    row['cells'], box = fbmOutput.blockMeshInfo(case)
    # a continued run: one log a part (log.fbmFoam, log.fbmFoam.<suffix>)
    cpu = [fbmOutput.cpuTime(log) for log in
           glob.glob(os.path.join(case, 'log.fbmFoam*'))]
    cpu = [c for c in cpu if c is not None]
    row['cpu_s'] = sum(cpu) if cpu else None

    frames = snapshotFrames(case, args.every)
    if not frames:
        print('%s: no cloud written and no constant/particles' % case)
        return 1
    r = 0.5*min(f[2].min() for f in frames)
    row['r'] = r
    row['N'] = int(s['N'][-1])
    t = s['Time']
    row['t_end'] = t[-1]
    row['mean_y_start'], row['mean_y_end'] = s['Xy'][0], s['Xy'][-1]
    i = np.argmax(s['maxSpeed'])
    row['max_speed'], row['t_max_speed'] = s['maxSpeed'][i], t[i]
    pairGap, tPair, wallGap, tWall = fbmOutput.largestOverlap(s)
    for key, g, tg in (('pair', pairGap, tPair), ('wall', wallGap, tWall)):
        row[key + '_overlap_r'] = 0.0 if g is None else max(0.0, -g/r)
        row['t_' + key] = tg if g is not None and g < 0 else None
    row['overlap_r'] = max(row['pair_overlap_r'], row['wall_overlap_r'])

    label = 'level %s, %s cells, %s disks, to t = %g' % (
        row.get('level', '?'),
        format(row['cells'], ',') if row['cells'] else '?',
        format(row['N'], ','), row['t_end'])
    if row['status'] not in ('0', 'none'):
        label += '\n(run failed: exit status %s)' % row['status']

    if box is None:
        # no blockMesh log: the cloud's extent rounded out
        allX = np.concatenate([f[1] for f in frames])
        box = ((min(0.0, allX[:, 0].min()), min(0.0, allX[:, 1].min()), 0),
               (math.ceil(allX[:, 0].max()), math.ceil(allX[:, 1].max()), 0))
    plotSnapshots(frames, box, 'sedimentation10k (fbmFoam): ' + label,
                  os.path.join(out, 'snapshots.png'), args.dpi)

    with open(os.path.join(out, 'meanHeight.csv'), 'w') as f:
        w = csv.writer(f, lineterminator='\n')
        w.writerow(['t', 'mean_y', 'max_speed', 'min_pair_gap',
                    'min_wall_gap'])
        for k in range(len(t)):
            w.writerow([fmt(t[k]), fmt(s['Xy'][k]), fmt(s['maxSpeed'][k])]
                       + [fmt(s[g][k]) if s[g][k] < 0.1*fbmOutput.GREAT
                          else '' for g in ('minPairGap', 'minWallGap')])
    plotMeanHeight(s, r, 'sedimentation10k: ' + label,
                   os.path.join(out, 'meanHeight.png'))

    # results.csv: this case's row replaces an earlier one of the same case
    path = os.path.join(out, 'results.csv')
    rows = []
    if os.path.isfile(path):
        with open(path) as f:
            rows = [x for x in csv.DictReader(f) if x['case'] != row['case']]
    rows.append({c: fmt(row.get(c)) for c in COLUMNS})
    with open(path, 'w') as f:
        w = csv.DictWriter(f, COLUMNS, lineterminator='\n',
                           extrasaction='ignore')
        w.writeheader()
        w.writerows(rows)

    print('%s: %s' % (case, label))
    print('snapshots at t = %s' % ', '.join('%g' % f[0] for f in frames))
    print('largest overlap: pairs %.4g r%s, walls %.4g r%s (r = %g)'
          % (row['pair_overlap_r'],
             '' if row['t_pair'] is None else ' at t = %g' % row['t_pair'],
             row['wall_overlap_r'],
             '' if row['t_wall'] is None else ' at t = %g' % row['t_wall'],
             r))
    print('wrote snapshots.png, meanHeight.csv, meanHeight.png, results.csv'
          ' in %s' % out)
    if row['status'] not in ('0', 'none'):
        print('Warning: the run has exit status %s (see %s/log.*)'
              % (row['status'], case))
    return 0


if __name__ == '__main__':
    sys.exit(main())
