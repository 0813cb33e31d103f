#!/usr/bin/python3
"""Collect and plot the big-disk runs of ./Allrun (runs/rho<RHO>-L<level>/).

For every run folder runs/rho<RHO>-L<level>[-random|-placed][-z<Z>]/ (a
copy of tutorials/fbmFoam/bigParticleDiving run with -rho RHO -level L
[-bed random|placed], its dampingRatio set to Z) reads

    system/caseParameters          rhoBig, level
    constant/fbmProperties         the radius R of the body 'big', the
                                   contacts' dampingRatio, projectContacts
    constant/smallParticles        the bed at the start (fbmSetParticles):
                                   its top max(y + r) and the small radius r
    <last time>/lagrangian/fbmBodies   the bodies at the last written time
    log.blockMesh                  cells, the cavity's bottom (bounding box)
    postProcessing/fbmBodies/*/big.dat, summary.dat   (joined over restarts)
    log.fbmFoam                    CPU time (ExecutionTime)

and writes

    results.csv   one row per run: rho, level, bed, zeta (dampingRatio),
                  projectContacts (yes/no), cells, t_end (last time
                  reached), y_start, y_min and t_y_min (the deepest point:
                  lowest centre height of the big disk and when), y_final
                  and Uy_final (centre height and vertical velocity at
                  t_end), reached_bottom (yes when y_min - bottom <= 1.05 R),
                  bed_top, t_cloud (the last written time), bed_top_end
                  (the bed's top then, away from the big disk: max(y + r) of the small
                  disks more than 2 R from its centre in x) and depth_end
                  (bed_top_end - (y - R) of the big disk then: how deep the big disk's
                  bottom is below it; < 0: above), pair_overlap_r and t_pair, wall_overlap_r and
                  t_wall (largest overlap of any pair / any disk with a
                  wall over the collision sub-steps, summary.dat, as a
                  fraction of the small radius r; 0 when none), n_bodies
                  (bodies in summary.dat), cpu_s, status (exit status of
                  the run, 'none' without exitStatus)
    height.png    the big disk's centre height against t for every run,
                  with the bed's top, the bottom and the centre heights of a
                  big disk resting on them

Usage: plotResults.py [RUNS] [SUFFIX]
    RUNS: default runs/ beside this script; SUFFIX: collect the runs
    rho<RHO>-L<level><SUFFIX> (SUFFIX as ./Allrun names them: none for the
    crystal bed, -random, -placed, each with -z<Z> for a dampingRatio Z
    and -pc / -nopc for projectContacts yes / no)
    into results<SUFFIX>.csv and height<SUFFIX>.png (default none)

status is the run's exit status, 'no bed' without constant/smallParticles,
'bodies' when summary.dat has another number of bodies than 1 + the small
disks of the bed; a warning is printed for each run whose status is not 0
(./Allrun's exit status says whether its runs failed). Exit status 1 when
no run could be read.
Run it with Debian's python3 (/usr/bin/python3, python3-matplotlib).
"""

import csv
import glob
import os
import re
import sys

import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, '..', '..', 'bin'))
import fbmOutput  # noqa: E402

import matplotlib  # noqa: E402
matplotlib.use('Agg')
import matplotlib.pyplot as plt  # noqa: E402

BIG = 'big'             # the big disk's body name (bodyFiles of the case)
BOTTOM_FACTOR = 1.05    # reached the bottom: centre within 1.05 R of it
# run folders: rho<RHO>-L<level>[-random|-placed][-z<Z>][-pc|-nopc]
RUN_NAME = re.compile(r'^rho([^-]+)-L(?:\d+)(-random|-placed)?(-z[^-/]+)?(-pc|-nopc)?$')


def bigRadius(run):
    text = open(os.path.join(run, 'constant', 'fbmProperties')).read()
    text = re.sub(r'//[^\n]*', '', text)
    m = re.search(r'\b' + BIG + r'\s*\{[^}]*?\bradius\s+([0-9.eE+-]+)\s*;',
                  text, re.S)
    if not m:
        raise RuntimeError('%s: no radius of body %s in constant/fbmProperties'
                           % (run, BIG))
    return float(m.group(1))


def dampingRatio(run):
    text = open(os.path.join(run, 'constant', 'fbmProperties')).read()
    text = re.sub(r'//[^\n]*', '', text)
    m = re.search(r'\bdampingRatio\s+([0-9.eE+-]+)\s*;', text)
    return float(m.group(1)) if m else 0.0


def projectContacts(run):
    v = fbmOutput.dictEntry(os.path.join(run, 'constant', 'fbmProperties'),
                            'projectContacts')
    return 'yes' if v in ('yes', 'on', 'true') else 'no'


def collect(run):
    row = {'run': run}
    params = os.path.join(run, 'system', 'caseParameters')
    row['rho'] = float(fbmOutput.dictEntry(params, 'rhoBig'))
    row['level'] = int(fbmOutput.dictEntry(params, 'level'))
    m = RUN_NAME.match(os.path.basename(run.rstrip('/')))
    row['bed'] = m.group(2)[1:] if m and m.group(2) else 'crystal'
    row['zeta'] = dampingRatio(run)
    row['projectContacts'] = projectContacts(run)
    try:
        row['status'] = open(os.path.join(run, 'exitStatus')).read().strip()
    except OSError:
        row['status'] = 'none'
    row['cells'], box = fbmOutput.blockMeshInfo(run)
    row['cpu_s'] = fbmOutput.cpuTime(os.path.join(run, 'log.fbmFoam'))
    R = bigRadius(run)
    row['R'] = R
    bed = os.path.join(run, 'constant', 'smallParticles')
    if not os.path.isfile(bed):
        print('%s: no constant/smallParticles (see %s/log.fbmSetParticles)'
              % (run, run))
        row['status'] = 'no bed'
        return row, None
    X, r = fbmOutput.readParticleList(bed)
    row['bed_top'] = (X[:, 1] + r).max()
    rSmall = r.min()
    row['bottom'] = box[0][1] if box else 0.0

    b = fbmOutput.history(run, BIG)
    s = fbmOutput.summary(run)
    if not b or not s:
        print('%s: no %s.dat or summary.dat (see %s/log.fbmFoam)'
              % (run, BIG, run))
        return row, None
    t, y = b['Time'], b['y']
    row['t_end'] = t[-1]
    row['y_start'] = y[0]
    i = np.argmin(y)
    row['y_min'], row['t_y_min'] = y[i], t[i]
    row['y_final'], row['Uy_final'] = y[-1], b['Uy'][-1]
    row['reached_bottom'] = \
        'yes' if y[i] - row['bottom'] <= BOTTOM_FACTOR*R else 'no'
    row['n_bodies'] = int(s['N'][-1])
    if row['n_bodies'] != 1 + len(r):
        print('%s: %d bodies in summary.dat, expected 1 + %d'
              % (run, row['n_bodies'], len(r)))
        row['status'] = 'bodies'
    times = fbmOutput.cloudTimes(run)
    if times:
        c = fbmOutput.readCloud(run, times[-1], fields=('d',))
        P, d = c['positions'], c['d']
        big = np.argmax(d)              # the big disk
        away = (d < 3*rSmall) & (np.abs(P[:, 0] - P[big, 0]) > 2*R)
        if away.any():
            row['t_cloud'] = float(times[-1])
            row['bed_top_end'] = (P[away, 1] + d[away]/2).max()
            row['depth_end'] = row['bed_top_end'] - (P[big, 1] - R)
    pairGap, tPair, wallGap, tWall = fbmOutput.largestOverlap(s)
    for key, g, tg in (('pair', pairGap, tPair), ('wall', wallGap, tWall)):
        row[key + '_overlap_r'] = 0.0 if g is None else max(0.0, -g/rSmall)
        row['t_' + key] = tg if g is not None and g < 0 else None
    return row, (t, y)


def fmt(v):
    if v is None:
        return ''
    if isinstance(v, (float, np.floating)):
        return '%.6g' % v
    return str(v)


def main():
    runs = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, 'runs')
    suffix = sys.argv[2] if len(sys.argv) > 2 else ''
    name = re.compile(r'^rho[^-]+-L\d+' + re.escape(suffix) + '$')
    found = [p for p in glob.glob(os.path.join(runs, 'rho*-L*'))
             if os.path.isdir(p) and name.match(os.path.basename(p))]
    if not found:
        sys.exit('No runs rho<RHO>-L<level>%s in %s: run ./Allrun first'
                 % (suffix, runs))

    rows, curves = [], []
    for run in found:
        row, curve = collect(run)
        rows.append(row)
        curves.append(curve)
    order = sorted(range(len(rows)),
                   key=lambda k: (rows[k]['bed'], rows[k]['level'],
                                  rows[k]['rho']))
    rows = [rows[k] for k in order]
    curves = [curves[k] for k in order]

    cols = ['rho', 'level', 'bed', 'zeta', 'projectContacts', 'cells', 't_end', 'y_start', 'y_min', 't_y_min',
            'y_final', 'Uy_final', 'reached_bottom', 'bed_top',
            't_cloud', 'bed_top_end', 'depth_end',
            'pair_overlap_r', 't_pair', 'wall_overlap_r', 't_wall',
            'n_bodies', 'cpu_s', 'status']
    out = os.path.join(here, 'results%s.csv' % suffix)
    with open(out, 'w') as f:
        w = csv.writer(f, lineterminator='\n')
        w.writerow(cols)
        for r in rows:
            w.writerow([fmt(r.get(c)) for c in cols])
    print(open(out).read(), end='')

    for r in rows:
        if r['status'] not in ('0', 'none'):
            print('Warning: rho %g level %d: status %s (see %s/log.*)'
                  % (r['rho'], r['level'], r['status'], r['run']))
    if all(c is None for c in curves):
        return 1
    plot(rows, curves, suffix)
    return 0


def plot(rows, curves, suffix):
    fig, ax = plt.subplots(figsize=(9.5, 7.5))
    colours = plt.rcParams['axes.prop_cycle'].by_key()['color']
    rhos = sorted(set(r['rho'] for r in rows))
    levels = sorted(set((r['bed'], r['level']) for r in rows))
    styles = ['-', '--', ':', '-.']
    for r, c in zip(rows, curves):
        if c is None:
            continue
        ax.plot(c[0], c[1], styles[levels.index((r['bed'], r['level'])) % 4],
                color=colours[rhos.index(r['rho']) % len(colours)],
                label='rho_s = %g, level %d (%s cells), %s bed, zeta %g%s, '
                'to t = %g'
                % (r['rho'], r['level'], format(r['cells'], ','), r['bed'],
                   r['zeta'], ', projectContacts'
                   if r['projectContacts'] == 'yes' else '', r['t_end']))
    # the lines of the first crystal run (the random bed's top is 0.04 lower)
    ref = next(r for r, c in zip(rows, curves) if c is not None)
    ref = next((r for r, c in zip(rows, curves)
                if c is not None and r['bed'] == 'crystal'), ref)
    R = ref['R']
    ax.axhline(ref['bed_top'], color='0.4', lw=1)
    ax.axhline(ref['bed_top'] + R, color='0.4', lw=0.8, ls='--')
    ax.axhline(ref['bottom'], color='k', lw=1.5)
    ax.axhline(ref['bottom'] + R, color='k', lw=0.8, ls='--')
    ax.text(0.99, ref['bed_top'], "bed's top at the start", color='0.4',
            ha='right', va='bottom', transform=ax.get_yaxis_transform(),
            fontsize=8)
    ax.text(0.99, ref['bed_top'] + R, 'big disk resting on it', color='0.4',
            ha='right', va='bottom', transform=ax.get_yaxis_transform(),
            fontsize=8)
    ax.text(0.99, ref['bottom'], 'bottom', ha='right', va='bottom',
            transform=ax.get_yaxis_transform(), fontsize=8)
    ax.text(0.99, ref['bottom'] + R, 'big disk on the bottom', ha='right',
            va='bottom', transform=ax.get_yaxis_transform(), fontsize=8)
    ax.set_ylim(ref['bottom'] - 0.1, max(r.get('y_start', 0) for r in rows)
                + 0.15)
    ax.set_xlabel('t [s]')
    ax.set_ylabel("big disk's centre height y [cm]")
    ax.set_title('Big disk (R = %g) diving into %d small ones (fbmFoam)'
                 % (R, ref.get('n_bodies', 1) - 1))
    ax.legend(fontsize=8, loc='upper center', bbox_to_anchor=(0.5, -0.1), ncol=2)
    fig.tight_layout()
    fig.savefig(os.path.join(here, 'height%s.png' % suffix), dpi=120,
                bbox_inches='tight')


if __name__ == '__main__':
    sys.exit(main())
