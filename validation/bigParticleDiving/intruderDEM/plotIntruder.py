#!/usr/bin/python3
"""Collect the Test-intruderDEM runs of ./Allrun: intruder.csv (one row per
run) and intruder.png (the big disk's centre height against t, one panel
per bed). Usage: plotIntruder.py [RUNS]  (default runs)"""
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


rows = []
series = {}
for f in sorted(glob.glob(os.path.join(runs, '*-c*-rho*.csv'))):
    m = re.match(r'(\w+)-c([\d.]+)-rho([\d.]+)\.csv', os.path.basename(f))
    bed, c, rho = m.group(1), float(m.group(2)), float(m.group(3))
    # complete rows only (a run still writing its file)
    data = [[float(x) for x in l] for l in list(csv.reader(open(f)))[1:]
            if len(l) == 6]
    t = [d[0] for d in data]
    y = [d[1] for d in data]
    i = min(range(len(y)), key=lambda k: y[k])
    top = bedTop(bed)
    gap = min(min(d[4] for d in data), min(d[5] for d in data))
    # at rest: |Uy| below 0.01 cm/s over the last 10 % of the run
    n = max(1, len(data)//10)
    rest = all(abs(d[2]) < 0.01 for d in data[-n:])
    rows.append({
        'bed': bed, 'damping': c, 'rho': rho, 't_end': t[-1],
        'bed_top': round(float(top), 4), 'y_min': round(y[i], 4),
        't_y_min': round(t[i], 3), 'y_final': round(y[-1], 4),
        'depth_in_bed': round(top - (y[-1] - R), 4),
        'reached_bottom': 'yes' if y[i] - R <= 0.05*R else 'no',
        'at_rest': 'yes' if rest else 'no',
        'max_overlap_r': round(max(0.0, -gap)/r, 4)})
    series[(bed, c, rho)] = (t, y)

if not rows:
    sys.exit('no runs in ' + runs)
with open('intruder.csv', 'w', newline='') as f:
    w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
    w.writeheader()
    w.writerows(rows)
for row in rows:
    print(row)

beds = sorted({k[0] for k in series})
colours = {1.1: 'tab:blue', 1.5: 'tab:orange', 2.0: 'tab:red'}
styles = {50.0: '-', 5.0: '--'}
fig, axs = plt.subplots(1, len(beds), figsize=(5.5*len(beds), 4.5), sharey=True)
if len(beds) == 1:
    axs = [axs]
for ax, bed in zip(axs, beds):
    top = bedTop(bed)
    for (b, c, rho), (t, y) in sorted(series.items()):
        if b != bed:
            continue
        ax.plot(t, y, styles.get(c, ':'), color=colours.get(rho, 'k'),
                label='rho %.1f, c = %g/s' % (rho, c))
    ax.axhline(top, color='0.5', lw=0.8)
    ax.axhline(top + R, color='0.5', lw=0.8, ls=':')
    ax.axhline(R, color='k', lw=0.8)
    ax.text(0.02, top + 0.02, 'bed top', color='0.4', fontsize=8,
            transform=ax.get_yaxis_transform())
    ax.text(0.02, R + 0.02, 'big disk on the bottom', fontsize=8,
            transform=ax.get_yaxis_transform())
    ax.set_title('%s bed, contact model alone (no fluid)' % bed)
    ax.set_xlabel('t [s]')
    ax.set_ylim(0, 4)
    ax.legend(fontsize=7, loc='lower right')
axs[0].set_ylabel('centre height of the big disk [cm]')
fig.tight_layout()
fig.savefig('intruder.png', dpi=110)
print('Wrote intruder.csv, intruder.png')
