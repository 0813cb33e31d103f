"""Tables and charts of the contact stability map.

map.csv, overlap.csv (Test-collisionMap) -> table.md, map.png, overlap.png
"""
import csv
import math
import os

import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt
from matplotlib.colors import LogNorm

here = os.path.dirname(os.path.abspath(__file__))


def read(name):
    rows = list(csv.DictReader(open(os.path.join(here, name))))
    for r in rows:
        for k, v in r.items():
            if k not in ('test', 'mode', 'status'):
                r[k] = float(v)
    return rows


rows = read('map.csv')
speed = read('overlap.csv')
epss = sorted({r['epsPOverlap'] for r in rows}, reverse=True)
ns = sorted({r['nStepsPerContact'] for r in rows if r['mode'] == 'scaled'})
u = rows[0]['u']
load = rows[0]['load']
dtFluid = 5e-3      # DKT tutorial maxDeltaT

# The law of Test-collisionMap (cgs, per unit length): the barrier of the
# range branch, Phi(s) = rho^3 (s/3 + rho/12)/eps_P, against the kinetic
# energy of two disks at +-u, rho_s pi R^2 u^2
R, rhoS, rangeRho, epsP = 0.1, 1.01, 1.5/24, 1e-5
s2 = 2*R
uCrit = math.sqrt(rangeRho**3*(s2/3 + rangeRho/12)/epsP
                  / (rhoS*math.pi*R**2))


def cell(test, eps, mode, n=None):
    for r in rows:
        if (r['test'] == test and r['epsPOverlap'] == eps
                and r['mode'] == mode
                and (n is None or r['nStepsPerContact'] == n)):
            return r
    return None


def energyError(r):
    """headOn: |KE after/before - 1|; rest: max |E - E0|/E_osc"""
    if r['test'] == 'headOn':
        return abs(r['energyRatio'] - 1)
    return r['energyErrMax']


def fmtCell(r, value):
    if r['status'] != 'ok':
        return '**%s**' % r['status']
    return value


with open(os.path.join(here, 'table.md'), 'w') as f:
    f.write('Contact stability map (Test-collisionMap, no fluid): disks R = '
            '0.1, rho_s = 1.01, rangePlusLinear law, range 0.0625, '
            'eps_P 1e-5, eps_W 5e-6, eps\'_W = eps\'_P/2 (cgs, 2D).\n'
            'headOn: two disks at +-%g cm/s; rest: one disk released '
            'touching the bottom wall under %g disk weights, for 0.1 s.\n\n'
            % (u, load))

    f.write('## Contact time and cost per stiffness (nStepsPerContact 20)\n\n'
            '| eps\'_P | t_c [s] | sub-step [s] | sub-steps per fluid step '
            '5e-3 | headOn overlap/R (law) | rest overlap/R (law) |\n'
            '|---|---|---|---|---|---|\n')
    for e in epss:
        h = cell('headOn', e, 'scaled', 20)
        s = cell('rest', e, 'scaled', 20)
        f.write('| %g | %.3g | %.3g | %d | %.4g (%.4g) | %.4g (%.4g) |\n'
                % (e, h['t_c'], h['dtSub'],
                   math.ceil(dtFluid/h['dtSub'] - 1e-12),
                   h['maxOverlapR'], h['overlapTheoryR'],
                   s['maxOverlapR'], s['overlapTheoryR']))

    for test, what in (
            ('headOn', 'kinetic energy after / before (1: elastic; failures '
             'in bold)'),
            ('rest', 'largest |E - E0| / oscillation energy over the run '
             '(failures in bold)')):
        f.write('\n## %s: %s\n\n' % (test, what))
        f.write('| eps\'_P | ' + ' | '.join('n = %g' % n for n in ns)
                + ' | fixed sub-step (n) |\n|---|' + '---|'*(len(ns) + 1)
                + '\n')
        for e in epss:
            cells = []
            for n in ns:
                r = cell(test, e, 'scaled', n)
                v = r['energyRatio'] if test == 'headOn' else r['energyErrMax']
                cells.append(fmtCell(r, '%.4g' % v))
            r = cell(test, e, 'fixed')
            v = r['energyRatio'] if test == 'headOn' else r['energyErrMax']
            cells.append('%s (%.3g)' % (fmtCell(r, '%.4g' % v), r['nEff']))
            f.write('| %g | %s |\n' % (e, ' | '.join(cells)))

    f.write('\nSmallest nStepsPerContact with no failure at any stiffness: ')
    for test in ('headOn', 'rest'):
        ok = [n for n in ns if all(cell(test, e, 'scaled', n)['status'] == 'ok'
                                   for e in epss)]
        f.write('%s %s; ' % (test, ('%g' % min(ok)) if ok else 'none'))
    f.write('\nLargest momentum error (headOn, all runs that did not fail): '
            '%.3g (M u)\n' % max(r['momentumErr'] for r in rows
                                 if r['test'] == 'headOn'
                                 and r['status'] == 'ok'))

    f.write('\n## headOn at nStepsPerContact 20: overlap/R against impact '
            'speed (law, from energy conservation, in brackets; below '
            'u_c = %.2f cm/s no overlap: the smallest gap/R)\n\n' % uCrit)
    us = sorted({r['u'] for r in speed})
    f.write('| eps\'_P | ' + ' | '.join('u = %g' % v for v in us)
            + ' |\n|---|' + '---|'*len(us) + '\n')
    for e in epss:
        cells = []
        for v in us:
            r = [x for x in speed if x['u'] == v and x['epsPOverlap'] == e][0]
            if r['status'] != 'ok':
                cells.append('**%s**' % r['status'])
            elif r['maxOverlapR'] > 0:
                cells.append('%.4g (%.4g)' % (r['maxOverlapR'],
                                              r['overlapTheoryR']))
            else:
                cells.append('gap %.3g (%.3g)' % (r['minGapR'],
                                                  -r['overlapTheoryR']))
        f.write('| %g | %s |\n' % (e, ' | '.join(cells)))

# -- map.png -------------------------------------------------------------------
fig, axes = plt.subplots(2, 2, figsize=(10, 7.5), sharex=True, sharey=True)
for col, test in enumerate(('headOn', 'rest')):
    for row, (what, key, norm) in enumerate((
            ('largest overlap / R', 'maxOverlapR', LogNorm(1e-5, 1)),
            ('energy error', None, LogNorm(1e-4, 1)))):
        ax = axes[row, col]
        sel = [r for r in rows if r['test'] == test]
        xs = [r['epsPOverlap'] for r in sel]
        ys = [r['nEff'] for r in sel]
        vals = [max(r[key] if key else energyError(r), 1e-12) for r in sel]
        markers = ['D' if r['mode'] == 'fixed' else 's' for r in sel]
        sc = None
        for m in ('s', 'D'):
            idx = [i for i, mm in enumerate(markers) if mm == m]
            sc = ax.scatter([xs[i] for i in idx], [ys[i] for i in idx],
                            c=[vals[i] for i in idx], norm=norm,
                            cmap='viridis', marker=m, s=80,
                            edgecolors='k', linewidths=0.5)
        fixed = sorted([r for r in sel if r['mode'] == 'fixed'],
                       key=lambda r: r['epsPOverlap'])
        ax.plot([r['epsPOverlap'] for r in fixed], [r['nEff'] for r in fixed],
                '--', color='grey', lw=0.8, zorder=0)
        bad = [r for r in sel if r['status'] != 'ok']
        ax.scatter([r['epsPOverlap'] for r in bad], [r['nEff'] for r in bad],
                   marker='x', c='red', s=110, linewidths=2)
        ax.axhline(20, color='k', lw=0.6, ls=':')
        ax.set_xscale('log')
        ax.set_yscale('log')
        title = ('head-on, u = +-%g cm/s' % u if test == 'headOn'
                 else 'rest on the wall, load %g weights' % load)
        if key is None:
            what = ('|KE after/before - 1|' if test == 'headOn'
                    else 'max |E - E0| / E_osc')
        ax.set_title('%s: %s' % (title, what), fontsize=9)
        ax.grid(True, which='both', alpha=0.3)
        fig.colorbar(sc, ax=ax)
        if row == 1:
            ax.set_xlabel("eps'_P [cm^3/dyn] (stiffer to the right)")
        if col == 0:
            ax.set_ylabel('sub-steps per contact time t_c')
axes[0, 0].invert_xaxis()      # shared by all four
handles = [
    axes[0, 0].scatter([], [], marker='s', c='grey', label='dt_s = t_c/n'),
    axes[0, 0].scatter([], [], marker='D', c='grey',
                       label='fixed dt_s = 2.05e-4 (DKT law, n = 20)'),
    axes[0, 0].scatter([], [], marker='x', c='red',
                       label='failed (NaN, crossed, energy gain > 10 %)')]
fig.legend(handles=handles, fontsize=8, loc='lower center', ncol=3)
fig.suptitle('Contact stability without fluid (singhRepulsion, '
             'velocity-Verlet sub-steps); dotted: default n = 20',
             fontsize=10)
fig.tight_layout(rect=(0, 0.04, 1, 1))
fig.savefig(os.path.join(here, 'map.png'), dpi=110)

# -- overlap.png ---------------------------------------------------------------
fig, ax = plt.subplots(figsize=(6, 4))
for v in sorted({r['u'] for r in speed}):
    sel = sorted([r for r in speed if r['u'] == v],
                 key=lambda r: r['epsPOverlap'])
    if all(r['maxOverlapR'] <= 0 for r in sel):
        continue
    line, = ax.plot([r['epsPOverlap'] for r in sel],
                    [min(r['overlapTheoryR'], 2) for r in sel], '-', lw=1)
    ok = [r for r in sel if r['status'] == 'ok']
    ax.plot([r['epsPOverlap'] for r in ok], [r['maxOverlapR'] for r in ok],
            'o', color=line.get_color(), label='u = +-%g cm/s' % v)
    bad = [r for r in sel if r['status'] != 'ok']
    ax.plot([r['epsPOverlap'] for r in bad], [1.0]*len(bad), 'x',
            color='red', ms=10, mew=2)
ax.plot([], [], 'x', color='red', label='crossed (overlap > R)')
ax.plot([], [], '-', color='grey',
        label='law (energy conservation; 2: no turning point)')
ax.axhline(1, color='k', lw=0.6, ls=':')
ax.set_xscale('log')
ax.set_yscale('log')
ax.invert_xaxis()
ax.set_xlabel("eps'_P [cm^3/dyn] (stiffer to the right)")
ax.set_ylabel('largest overlap / R')
ax.set_title('Head-on overlap, nStepsPerContact 20 (none below u = %.2f '
             'cm/s)' % uCrit, fontsize=9)
ax.grid(True, which='both', alpha=0.3)
ax.legend(fontsize=7)
fig.tight_layout()
fig.savefig(os.path.join(here, 'overlap.png'), dpi=110)
print('wrote table.md, map.png, overlap.png')
