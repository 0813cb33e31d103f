"""Table and chart of the stability sweep (sweep.csv -> table.md, sweep.png)."""
import csv
import os

import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt

here = os.path.dirname(os.path.abspath(__file__))
rows = list(csv.DictReader(open(os.path.join(here, 'sweep.csv'))))
rhos = sorted({float(r['rho_s']) for r in rows}, reverse=True)
Cas = sorted({float(r['Ca']) for r in rows})
cell = {(float(r['rho_s']), float(r['Ca'])): r for r in rows}

with open(os.path.join(here, 'table.md'), 'w') as f:
    f.write('Settling particle (rho_s/rho_f < 1: rising), nu = 0.1, level 3 '
            '(R/h = 3), dt = 1e-3, to t = 0.3 (or the wall): status (v at '
            'the end, oscillation index)\n\n')
    f.write('| rho_s/rho_f | ' + ' | '.join('C_a = %g' % c for c in Cas)
            + ' |\n|---|' + '---|'*len(Cas) + '\n')
    for rho in rhos:
        cells = []
        for c in Cas:
            r = cell.get((rho, c))
            if r is None:
                cells.append('-')
            elif r['status'] == 'diverged':
                cells.append('**diverged** at t = %s' % r['t_end'])
            else:
                cells.append('%s (v = %.3f, osc %.2g)'
                             % (r['status'], float(r['v_end']), float(r['osc'])))
        f.write('| %g | %s |\n' % (rho, ' | '.join(cells)))
    f.write('\nLowest density ratio that runs stably (settling; rising):'
            '\n\n')
    for c in Cas:
        ok = [rho for rho in rhos
              if cell.get((rho, c), {}).get('status') == 'stable']
        heavy = [rho for rho in ok if rho > 1]
        light = [rho for rho in ok if rho < 1]
        f.write('- C_a = %g: %s; %s\n'
                % (c, ('%g' % min(heavy)) if heavy else 'none',
                   ('%g' % min(light)) if light else 'none'))

colour = {'stable': 'tab:green', 'oscillating': 'tab:orange',
          'diverged': 'tab:red'}
fig, ax = plt.subplots(figsize=(7.5, 3.5))
for r in rows:
    ax.scatter(float(r['rho_s']) - 1, float(r['Ca']), s=120,
               c=colour[r['status']], marker='o' if r['status'] != 'diverged'
               else 'x')
for s, c in colour.items():
    ax.scatter([], [], c=c, label=s, marker='x' if s == 'diverged' else 'o')
# rho_s/rho_f - 1 < 0: a light disk rising
ax.set_xscale('symlog', linthresh=0.01)
ax.axvline(0, color='k', lw=0.8)
ax.set_xlabel('rho_s/rho_f - 1 (< 0: rising)')
ax.set_ylabel('addedMassCoeff C_a')
ax.set_title('Explicit coupling: settling / rising disk, dt = 1e-3, R/h = 3')
ax.legend(loc='center left', bbox_to_anchor=(1.02, 0.5), fontsize=8)
ax.grid(True, which='both', alpha=0.3)
fig.tight_layout()
fig.savefig(os.path.join(here, 'sweep.png'), dpi=120)
print('wrote table.md, sweep.png')
