#!/usr/bin/python3
"""Collect and plot the DKT runs of ./Allrun (runs/level<L>/).

For every run folder runs/level<L>/ (a copy of tutorials/fbmFoam/DKT run
with -level L), runs that copy's dkt.py (the tutorial's definitions of
kissing and tumbling: gap below the repulsion range 1.5 h; the trailing
disk level with or below the leading one), reads its dkt.csv and output,
the body histories, summary.dat, log.blockMesh and log.fbmFoam, and writes

    results.csv       one row per level: level, cells, h, t_end (last time
                      reached), kiss_start, kiss_end, min_gap, t_min_gap,
                      tumble, max_speed (largest |U| of either disk),
                      min_wall_gap, overlap_R (largest overlap, pair or
                      wall, over the collision sub-steps of summary.dat, as
                      a fraction of the disk radius; 0 when none), cpu_s
                      (fbmFoam's ExecutionTime), status (exit status of
                      the run; 'none' when runs/ has no exitStatus)
    trajectories.csv  level, t, x_lower, y_lower, x_upper, y_upper, gap
                      (every time step of every level)
    dkt.png           y, x and the surface gap of both disks against t for
                      each level; the kissing window t = 1.0-1.6 of
                      reference.md section 3 shaded

Usage: plotResults.py [RUNS [SUFFIX]]   (default: runs/ beside this script;
SUFFIX names the outputs results<SUFFIX>.csv, trajectories<SUFFIX>.csv and
dkt<SUFFIX>.png, as ./Allrun -coupling NAME does with -NAME)

Prints a warning for each run whose exit status is not 0 (./Allrun's exit
status says whether its runs failed). Exit status 1 when no run could be
read or one run's output is unreadable.
Run it with Debian's python3 (/usr/bin/python3, python3-matplotlib).
"""

import csv
import glob
import os
import re
import subprocess
import sys

import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, '..', '..', 'bin'))
import fbmOutput  # noqa: E402

import matplotlib  # noqa: E402
matplotlib.use('Agg')
import matplotlib.pyplot as plt  # noqa: E402

# Glowinski et al. (2001) kissing window, reference.md section 3
KISS_REF = (1.0, 1.6)


def num(s):
    return None if s in (None, 'None') else float(s)


def runDkt(run):
    """The run's dkt.py: its printed times and dkt.csv (numpy, named)."""
    p = subprocess.run([sys.executable, os.path.join(run, 'dkt.py'), run],
                       stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                       universal_newlines=True)
    if p.returncode != 0:
        raise RuntimeError('dkt.py failed in %s:\n%s' % (run, p.stdout))
    out = p.stdout
    patterns = {
        'h': r'level \d+: h = (\S+),',
        'kiss': r'kissing \(gap < range\): from t = (\S+) to t = (\S+)',
        'gap': r'smallest gap (\S+) \(\S+ h\) at t = (\S+)',
        'tumble': r'tumbling .*: t = (\S+)',
    }
    found = {}
    for key, pat in patterns.items():
        m = re.search(pat, out)
        if not m:
            raise RuntimeError('%s: dkt.py output not understood (%s):\n%s'
                               % (run, key, out))
        found[key] = [num(g) for g in m.groups()]
    traj = np.genfromtxt(os.path.join(run, 'dkt.csv'), delimiter=',',
                         names=True)
    return found, traj


def bodies(run):
    """Names of the per-body histories (no summary, no compared models)."""
    names = set()
    for f in glob.glob(os.path.join(run, 'postProcessing', 'fbmBodies', '*',
                                    '*.dat')):
        name = os.path.basename(f)[:-4]
        if name != 'summary' and '.' not in name:
            names.add(name)
    return sorted(names)


def collect(run, level):
    row = {'level': level}
    try:
        row['status'] = open(os.path.join(run, 'exitStatus')).read().strip()
    except OSError:
        row['status'] = 'none'
    cells, box = fbmOutput.blockMeshInfo(run)
    row['cells'] = cells
    row['cpu_s'] = fbmOutput.cpuTime(os.path.join(run, 'log.fbmFoam'))

    s = fbmOutput.summary(run)
    if not s:
        print('%s: no summary.dat (see %s/log.fbmFoam)' % (run, run))
        return row, None
    row['t_end'] = s['Time'][-1]

    found, traj = runDkt(run)
    row['h'] = found['h'][0]
    row['kiss_start'], row['kiss_end'] = found['kiss']
    row['min_gap'], row['t_min_gap'] = found['gap']
    row['tumble'] = found['tumble'][0]

    row['max_speed'] = max(
        np.sqrt(b['Ux']**2 + b['Uy']**2 + b['Uz']**2).max()
        for b in (fbmOutput.history(run, n) for n in bodies(run)))

    pairGap, _, wallGap, _ = fbmOutput.largestOverlap(s)
    row['min_wall_gap'] = wallGap
    times = fbmOutput.cloudTimes(run)
    if times:
        R = 0.5*fbmOutput.readCloud(run, times[-1], ('d',))['d'].min()
        gaps = [g for g in (pairGap, wallGap) if g is not None]
        row['overlap_R'] = max([0.0] + [-g/R for g in gaps])
    return row, traj


def fmt(v):
    if v is None:
        return ''
    if isinstance(v, float):
        return '%.6g' % v
    return str(v)


def main():
    runs = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, 'runs')
    suffix = sys.argv[2] if len(sys.argv) > 2 else ''
    found = []
    for run in glob.glob(os.path.join(runs, 'level*')):
        m = re.match(r'level(\d+)$', os.path.basename(run))
        if m:
            found.append((int(m.group(1)), run))
    if not found:
        sys.exit('No runs in %s: run ./Allrun first' % runs)

    rows, trajs = [], []
    for level, run in sorted(found):
        row, traj = collect(run, level)
        rows.append(row)
        if traj is not None:
            trajs.append((level, traj))

    cols = ['level', 'cells', 'h', 't_end', 'kiss_start', 'kiss_end',
            'min_gap', 't_min_gap', 'tumble', 'max_speed', 'min_wall_gap',
            'overlap_R', 'cpu_s', 'status']
    with open(os.path.join(here, 'results%s.csv' % suffix), 'w') as f:
        w = csv.writer(f, lineterminator='\n')
        w.writerow(cols)
        for r in rows:
            w.writerow([fmt(r.get(c)) for c in cols])
    print(open(os.path.join(here, 'results%s.csv' % suffix)).read(), end='')

    with open(os.path.join(here, 'trajectories%s.csv' % suffix), 'w') as f:
        w = csv.writer(f, lineterminator='\n')
        names = ['t', 'x_lower', 'y_lower', 'x_upper', 'y_upper', 'gap']
        w.writerow(['level'] + names)
        for level, t in trajs:
            for i in range(len(t)):
                w.writerow([level] + ['%.6g' % t[n][i] for n in names])

    for r in rows:
        if r['status'] not in ('0', 'none'):
            print('Warning: level %d: exit status %s (see %s/log.*)'
                  % (r['level'], r['status'],
                     os.path.join(runs, 'level%d' % r['level'])))
    if not trajs:
        return 1
    plot(trajs, rows, suffix)
    return 0


def plot(trajs, rows, suffix=""):
    fig, ax = plt.subplots(3, 1, figsize=(8, 10), sharex=True)
    colours = plt.rcParams['axes.prop_cycle'].by_key()['color']
    info = {r['level']: r for r in rows}
    for k, (level, t) in enumerate(trajs):
        c = colours[k % len(colours)]
        r = info[level]
        lab = 'level %d (%s cells, to t = %g)' % (
            level, format(r['cells'], ',') if r['cells'] else '?',
            r['t_end'])
        ax[0].plot(t['t'], t['y_lower'], '-', color=c, label=lab)
        ax[0].plot(t['t'], t['y_upper'], '--', color=c)
        ax[1].plot(t['t'], t['x_lower'], '-', color=c)
        ax[1].plot(t['t'], t['x_upper'], '--', color=c)
        ax[2].plot(t['t'], t['gap'], '-', color=c)
        ax[2].axhline(1.5*r['h'], color=c, lw=0.8, ls=':')
        for a in ax:
            for key, ls in (('kiss_start', '-.'), ('tumble', ':')):
                if r.get(key) is not None:
                    a.axvline(r[key], color=c, lw=0.8, ls=ls)
    for a in ax:
        a.axvspan(*KISS_REF, color='0.85', zorder=0)
    ax[0].set_ylabel('y [cm]')
    ax[1].set_ylabel('x [cm]')
    ax[2].set_ylabel('surface gap D - 2R [cm]')
    ax[2].set_yscale('log')
    ax[2].set_xlabel('t [s]')
    ax[0].plot([], [], 'k-', label='lower (leading) disk')
    ax[0].plot([], [], 'k--', label='upper (trailing) disk')
    ax[0].fill_between([], [], color='0.85',
                       label='kissing, Glowinski et al. 2001: t = 1.0-1.6')
    ax[0].plot([], [], 'k-.', lw=0.8, label='kissing starts (gap < 1.5 h)')
    ax[0].plot([], [], 'k:', lw=0.8, label='tumbling (trailing disk level)')
    ax[0].legend(fontsize=8, loc='lower left')
    ax[2].plot([], [], 'k:', lw=0.8, label='repulsion range 1.5 h')
    ax[2].legend(fontsize=8)
    ax[0].set_title('DKT: two disks, rho_s/rho_f = 1.01 (fbmFoam%s)'
                    % suffix.replace('-backward', ', backward')
                    .replace('-', ', coupling '))
    fig.tight_layout()
    fig.savefig(os.path.join(here, 'dkt%s.png' % suffix), dpi=120)


if __name__ == '__main__':
    sys.exit(main())
