"""Table and chart of the viscous-limit map (AllrunViscous).

Reads viscousMap.csv; writes viscousTable.md (one row per level and time
scheme, one column per nominal viscous ratio r: the status and the
oscillation index; and the first failing r, also as the coupling's ratio
r/(1 + w), w = 1/2 for backward at a constant step, 0 for Euler) and
viscousMap.png (the oscillation index against r and against r/(1 + w),
the diverged runs marked at the top).
"""
import csv
import math

import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt

rows = list(csv.DictReader(open('viscousMap.csv')))
names = {'S': 'semiImplicit, Euler', 'SB': 'semiImplicit, backward',
         'SBN': 'semiImplicit, backward, pressureSolve newton',
         'SBL': 'semiImplicit, backward, rho_s 0.55',
         'SBNL': 'semiImplicit, backward, pressureSolve newton, rho_s 0.55'}
keys = []
for r in rows:
    k = (r['level'], r['Ca'])
    if k not in keys:
        keys.append(k)
rs = sorted({float(r['r']) for r in rows})

# The inertial part of the diagonal, (1 + w) V/dt, over V/dt
inertia = {'S': 1.0, 'SB': 1.5, 'SBN': 1.5, 'SBL': 1.5, 'SBNL': 1.5}
short = {'stable': 'S', 'oscillating': 'O', 'diverged': 'D'}
with open('viscousTable.md', 'w') as f:
    f.write('Status at nominal viscous ratio r = 4 nu dt/h^2 (S stable, '
            'O oscillating, D diverged; the oscillation index in %):\n\n')
    f.write('| level (R/h) | scheme | '
            + ' | '.join('%g' % x for x in rs)
            + ' | first failing r | as r/(1 + w) |\n')
    f.write('|---|---|' + '---|'*len(rs) + '---|---|\n')
    for lv, ca in keys:
        cells = []
        for x in rs:
            m = [r for r in rows if (r['level'], r['Ca']) == (lv, ca)
                 and float(r['r']) == x]
            if not m:
                cells.append('')
            elif m[0]['status'] == 'diverged':
                cells.append('D')
            else:
                cells.append('%s %.1f' % (short[m[0]['status']],
                                          100*float(m[0]['osc'])))
        fail = [float(r['r']) for r in rows if (r['level'], r['Ca']) == (lv, ca)
                and r['status'] != 'stable']
        first = '%g' % min(fail) if fail else '-'
        scaled = '%.3g' % (min(fail)/inertia[ca]) if fail else '-'
        f.write('| %s (%d) | %s | %s | %s | %s |\n'
                % (lv, 3*2**(int(lv) - 3), names.get(ca, ca),
                   ' | '.join(cells), first, scaled))

fig, axes = plt.subplots(1, 2, figsize=(11, 4.5), sharey=True)
styles = {'S': '-', 'SB': '--', 'SBN': ':', 'SBL': '-.', 'SBNL': (0, (1, 3))}
colours = {'3': 'C0', '4': 'C1'}
for panel, ax in enumerate(axes):
    for lv, ca in keys:
        f = inertia[ca] if panel else 1.0
        m = sorted((r for r in rows if (r['level'], r['Ca']) == (lv, ca)),
                   key=lambda r: float(r['r']))
        x = [float(r['r'])/f for r in m if r['status'] != 'diverged']
        y = [max(100*float(r['osc']), 1e-3) for r in m
             if r['status'] != 'diverged']
        ax.plot(x, y, linestyle=styles.get(ca, ':'),
                marker={'SB': 's', 'SBL': 'v', 'SBNL': '^'}.get(ca, 'o'),
                color=colours.get(lv, 'k'),
                label='R/h %d, %s' % (3*2**(int(lv) - 3), names.get(ca, ca)))
        xd = [float(r['r'])/f for r in m if r['status'] == 'diverged']
        ax.scatter(xd, [0.98]*len(xd), marker='x', color=colours.get(lv, 'k'),
                   transform=ax.get_xaxis_transform(), clip_on=False)
    ax.axhline(2, color='grey', lw=0.8)
    ax.text(min(rs)/(1.5 if panel else 1), 2.3, 'oscillating above 2 %',
            color='grey', fontsize=8)
    if panel:
        ax.axvline(1.6, color='k', lw=0.6, ls=':')
    ax.set_yscale('log')
    ax.set_xlabel('r / (1 + w): the coupling\'s ratio (default limit 1.6 dotted)'
                  if panel else 'nominal viscous ratio r = 4 nu dt / h$^2$')
axes[0].set_ylabel('oscillation index of U_y, last 50 steps [%]')
axes[0].legend(fontsize=8)
fig.suptitle('Settling disk, rho_s 1.5 (rising, 0.55: the light variants),'
             ' fixed step: the viscous step limit (x: diverged)')
fig.tight_layout()
fig.savefig('viscousMap.png', dpi=110)
