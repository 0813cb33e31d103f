#!/usr/bin/python3
"""Collect the Test-intruderDEM runs of ./Allrun: intruder.csv (one row per
run) and intruder.png (the big disk's centre height against t, one panel
per bed); the runs of ./Allrun -printed (the paper's law as printed, bed
names crystal-printed-e<eps'_P>) go to intruder-printed.csv and
intruder-printed.png. Usage: plotIntruder.py [RUNS]  (default runs)"""
import csv
import glob
import os
import re
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, '..', '..', '..', 'bin'))
import fbmOutput  # noqa: E402

import matplotlib  # noqa: E402
matplotlib.use('Agg')
import matplotlib.pyplot as plt  # noqa: E402

R, r = 0.2, 0.025          # big and small radius (the tutorial's)
runs = sys.argv[1] if len(sys.argv) > 1 else 'runs'


def bedTop(bed):
    """max(y + r) of the settled bed of runs/bed-<bed>"""
    X, rad = fbmOutput.readParticleList(
        os.path.join(runs, 'bed-' + bed, 'constant', 'smallParticles'))
    return (X[:, 1] + rad).max()


def status(csvFile):
    """'end' when the run reached its end time, 'crossed wall' when a disk
    crossed a wall (the run stopped there), else 'running or failed'"""
    log = open(csvFile[:-4] + '.log').read()
    if re.search(r'^End', log, re.M):
        return 'end'
    if 'has crossed the wall' in log:
        return 'crossed wall'
    return 'running or failed'


rows = []
series = {}
for f in sorted(glob.glob(os.path.join(runs, '*-c*-rho*.csv'))):
    m = re.match(r'(.+)-c([\d.]+)-rho([\d.]+)\.csv', os.path.basename(f))
    bed, c, rho = m.group(1), float(m.group(2)), float(m.group(3))
    # complete rows only (a run still writing its file)
    data = [[float(x) for x in l] for l in list(csv.reader(open(f)))[1:]
            if len(l) == 6]
    if not data:
        continue
    t = [d[0] for d in data]
    y = [d[1] for d in data]
    i = min(range(len(y)), key=lambda k: y[k])
    top = bedTop(bed)
    pair = min(d[4] for d in data)
    wall = min(d[5] for d in data)
    # at rest: |Uy| below 0.01 cm/s over the last 10 % of the run
    n = max(1, len(data)//10)
    rest = all(abs(d[2]) < 0.01 for d in data[-n:])
    row = {
        'bed': bed, 'damping': c, 'rho': rho, 't_end': t[-1],
        'bed_top': round(float(top), 4), 'y_min': round(y[i], 4),
        't_y_min': round(t[i], 3), 'y_final': round(y[-1], 4),
        'depth_in_bed': round(top - (y[-1] - R), 4),
        'reached_bottom': 'yes' if y[i] - R <= 0.05*R else 'no',
        'at_rest': 'yes' if rest else 'no',
        'max_overlap_r': round(max(0.0, -pair, -wall)/r, 4)}
    if 'printed' in bed:
        row['eps_overlap'] = float(bed.split('-e', 1)[1])
        row['pair_overlap_r'] = round(max(0.0, -pair)/r, 4)
        row['wall_overlap_r'] = round(max(0.0, -wall)/r, 4)
        row['status'] = status(f)
    rows.append(row)
    series[(bed, c, rho)] = (t, y)

if not rows:
    sys.exit('no runs in ' + runs)


def write(name, group):
    if not group:
        return
    with open(name + '.csv', 'w', newline='') as f:
        w = csv.DictWriter(f, fieldnames=list(group[0].keys()))
        w.writeheader()
        w.writerows(group)
    for row in group:
        print(row)

    beds = sorted({row['bed'] for row in group},
                  key=lambda b: (-float(b.split('-e', 1)[1])
                                 if 'printed' in b else b))
    colours = {1.1: 'tab:blue', 1.5: 'tab:orange', 2.0: 'tab:red'}
    styles = {50.0: '-', 5.0: '--'}
    fig, axs = plt.subplots(1, len(beds), figsize=(5.0*len(beds), 4.5),
                            sharey=True, squeeze=False)
    for ax, bed in zip(axs[0], beds):
        top = bedTop(bed)
        crossed = False
        for row in group:
            if row['bed'] != bed:
                continue
            c, rho = row['damping'], row['rho']
            t, y = series[(bed, c, rho)]
            ax.plot(t, y, styles.get(c, ':'), color=colours.get(rho, 'k'),
                    label='rho %.1f, c = %g/s' % (rho, c))
            if row.get('status') == 'crossed wall':
                ax.plot(t[-1], y[-1], 'x', color=colours.get(rho, 'k'))
                crossed = True
        ax.axhline(top, color='0.5', lw=0.8)
        ax.axhline(top + R, color='0.5', lw=0.8, ls=':')
        ax.axhline(R, color='k', lw=0.8)
        ax.text(0.02, top + 0.02, 'bed top', color='0.4', fontsize=8,
                transform=ax.get_yaxis_transform())
        ax.text(0.02, R + 0.02, 'big disk on the bottom', fontsize=8,
                transform=ax.get_yaxis_transform())
        if 'printed' in bed:
            ax.set_title("law as printed, eps'_P = %s%s"
                         % (bed.split('-e', 1)[1],
                            '\n(x: a disk crossed a wall, run stopped)'
                            if crossed else ''), fontsize=9)
        else:
            ax.set_title('%s bed, contact model alone (no fluid)' % bed)
        ax.set_xlabel('t [s]')
        ax.set_ylim(0, 4)
        ax.legend(fontsize=7, loc='lower right')
    axs[0][0].set_ylabel('centre height of the big disk [cm]')
    fig.tight_layout()
    fig.savefig(name + '.png', dpi=110)
    print('Wrote %s.csv, %s.png' % (name, name))


write('intruder', [row for row in rows if 'printed' not in row['bed']])
write('intruder-printed', [row for row in rows if 'printed' in row['bed']])
