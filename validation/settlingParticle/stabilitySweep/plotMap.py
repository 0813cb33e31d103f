"""Stability map in (density ratio, time step): map.csv and the dt = 1e-3
runs of sweep.csv -> mapTable.md, map.png."""
import csv
import os

import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt

here = os.path.dirname(os.path.abspath(__file__))
rows = list(csv.DictReader(open(os.path.join(here, 'map.csv'))))
have = {(r['rho_s'], r['Ca'], float(r['dt'])) for r in rows}
for r in csv.DictReader(open(os.path.join(here, 'sweep.csv'))):
    if (r['rho_s'], r['Ca'], 1e-3) not in have and r['Ca'] in ('0', '1'):
        r = dict(r)
        r['dt'] = '1e-3'
        rows.append(r)


COUPLINGS = {'P': 'coupling rigidProjection', 'S': 'coupling semiImplicit',
             'B': 'explicit, addedMassCoeff C_a = 1, backward time scheme '
                  '(the tutorial since 2026-12-05; the others Euler)',
             'SB': 'coupling semiImplicit, backward time scheme',
             'SBs': 'coupling semiImplicit, backward, impulse solved',
             'SBN': 'coupling semiImplicit, backward, pressureSolve newton'}


def key(c):
    """Coupling label: C_a as a number, then 'P' (rigidProjection), 'S'
    (semiImplicit), 'B' (C_a 1 with backward), 'SB' (semiImplicit
    with backward), 'SBs' (the same with impulse solved) and 'SBN' (with
    pressureSolve newton)."""
    return (1, c) if c in COUPLINGS else (0, float(c))


def title(c):
    if c in COUPLINGS:
        return COUPLINGS[c]
    return 'explicit, addedMassCoeff C_a = %g' % float(c)


for r in rows:
    r['Ca'] = r['Ca'] if r['Ca'] in COUPLINGS else '%g' % float(r['Ca'])
Cas = sorted({r['Ca'] for r in rows}, key=key)
dts = sorted({float(r['dt']) for r in rows})
rhos = sorted({float(r['rho_s']) for r in rows}, reverse=True)
cell = {(float(r['rho_s']), r['Ca'], float(r['dt'])): r for r in rows}

with open(os.path.join(here, 'mapTable.md'), 'w') as f:
    f.write('Settling particle (rho_s/rho_f < 1: rising), nu = 0.1, '
            'level 3 (R/h = 3), fixed dt, to '
            't = 0.3: s = stable, o = oscillating, d = diverged (at t)\n\n')
    for c in Cas:
        f.write('%s\n\n| rho_s/rho_f | ' % title(c)
                + ' | '.join('dt = %g' % d for d in dts)
                + ' |\n|---|' + '---|'*len(dts) + '\n')
        for rho in rhos:
            out = []
            for d in dts:
                r = cell.get((rho, c, d))
                if r is None:
                    out.append('-')
                elif r['status'] == 'diverged':
                    out.append('d (%s)' % r['t_end'])
                else:
                    out.append(r['status'][0])
            f.write('| %g | %s |\n' % (rho, ' | '.join(out)))
        f.write('\n')

colour = {'stable': 'tab:green', 'oscillating': 'tab:orange',
          'diverged': 'tab:red'}
fig, axes = plt.subplots(1, len(Cas), figsize=(5*len(Cas), 3.6), sharey=True)
if len(Cas) == 1:
    axes = [axes]
for ax, c in zip(axes, Cas):
    for r in rows:
        if r['Ca'] != c:
            continue
        s = r['status']
        ax.scatter(float(r['rho_s']) - 1, float(r['dt']), s=110,
                   c=colour[s], marker='x' if s == 'diverged' else 'o')
    for s, col in colour.items():
        ax.scatter([], [], c=col, label=s,
                   marker='x' if s == 'diverged' else 'o')
    # rho_s/rho_f - 1 < 0: a light disk rising
    ax.set_xscale('symlog', linthresh=0.01)
    ax.axvline(0, color='k', lw=0.8)
    ax.set_yscale('log')
    ax.set_xlabel('rho_s/rho_f - 1 (< 0: rising)')
    ax.set_title(title(c), fontsize=10)
    ax.grid(True, which='both', alpha=0.3)
axes[0].set_ylabel('time step dt')
axes[-1].legend(loc='center left', bbox_to_anchor=(1.02, 0.5), fontsize=8)
fig.suptitle('Settling / rising disk (R/h = 3): where the couplings fail')
fig.tight_layout()
fig.savefig(os.path.join(here, 'map.png'), dpi=120)
print('wrote mapTable.md, map.png')
