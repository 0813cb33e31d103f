"""Table and chart of the friction on an incline.

results.csv (Test-friction -csv, frictionModel velocityRegularised; bodies
block, blockNotTurning, disk and blockOnSlab),
results-spring.csv (-model tangentialSpring) -> table.md, table-spring.md,
friction.png
"""
import csv
import math
import os

import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt

here = os.path.dirname(os.path.abspath(__file__))
def read(name):
    rows = list(csv.DictReader(open(os.path.join(here, name))))
    for r in rows:
        for k in r:
            if k != 'body':
                r[k] = float(r[k])
    return rows


rows = read('results.csv')
spring = read('results-spring.csv')

g, theta = 10.0, math.radians(20)
names = {'block': 'block 0.2 x 0.1 (turns)',
         'blockNotTurning': 'block, rotation off',
         'disk': 'disk R 0.1 (turns)',
         'blockOnSlab': 'block on a fixed slab (turns)'}

# Table: acceleration against the exact one, creep where held
with open(os.path.join(here, 'table.md'), 'w') as t:
    t.write('| mu | block a | block, rotation off a | disk a | block on a '
            'slab a | exact a: block / disk | disk slip (U + omega R)/U | '
            'held: creep speed, block / rotation off / on a slab |\n')
    t.write('|---|---|---|---|---|---|---|---|\n')
    for mu in sorted({r['mu'] for r in rows}):
        b, n, d, s = (next(r for r in rows if r['body'] == k and r['mu'] == mu)
                      for k in ('block', 'blockNotTurning', 'disk',
                                'blockOnSlab'))
        held = b['a_exact'] == 0
        t.write('| %g | %.4f | %.4f | %.4f | %.4f | %.4f / %.4f | %.4f | %s |\n'
                % (mu, b['a'], n['a'], d['a'], s['a'], b['a_exact'],
                   d['a_exact'], d['slip'],
                   '%.2g / %.2g / %.2g m/s' % (b['U_end'], n['U_end'],
                                               s['U_end']) if held
                   else '-'))

# The spring: the same table, the held bodies' corner slid in 0.5 s
with open(os.path.join(here, 'table-spring.md'), 'w') as t:
    t.write('| mu | block a | block, rotation off a | disk a | block on a '
            'slab a | exact a: block / disk | disk slip (U + omega R)/U | '
            'held: front corner slid in 0.5 s, block / rotation off '
            '(velocityRegularised) |\n')
    t.write('|---|---|---|---|---|---|---|---|\n')
    for mu in sorted({r['mu'] for r in spring}):
        b, n, d, s = (next(r for r in spring if r['body'] == k and r['mu'] == mu)
                      for k in ('block', 'blockNotTurning', 'disk',
                                'blockOnSlab'))
        b0, n0 = (next(r for r in rows if r['body'] == k and r['mu'] == mu)
                  for k in ('block', 'blockNotTurning'))
        held = b['a_exact'] == 0
        t.write('| %g | %.4f | %.4f | %.4f | %.4f | %.4f / %.4f | %.4f | %s |\n'
                % (mu, b['a'], n['a'], d['a'], s['a'], b['a_exact'],
                   d['a_exact'], d['slip'],
                   '%.2g / %.2g m (%.2g / %.2g m)'
                   % (b['corner_slip'], n['corner_slip'], b0['corner_slip'],
                      n0['corner_slip']) if held else '-'))

fig, ax = plt.subplots(1, 2, figsize=(11, 4.2))
mus = [i*0.005 for i in range(0, 121)]
ax[0].plot(mus, [g*max(math.sin(theta) - m*math.cos(theta), 0) for m in mus],
           'k-', lw=1, label='exact, block')
ax[0].plot(mus, [(2/3*g*math.sin(theta) if m >= math.tan(theta)/3
                  else g*(math.sin(theta) - m*math.cos(theta))) for m in mus],
           'k--', lw=1, label='exact, disk (rolls from tan/3)')
for k, mk in (('block', 'o'), ('blockNotTurning', 'x'), ('disk', 's'),
              ('blockOnSlab', '+')):
    sel = [r for r in rows if r['body'] == k]
    ax[0].plot([r['mu'] for r in sel], [r['a'] for r in sel], mk,
               mfc='none', label=names[k])
ax[0].set_xlabel('friction coefficient mu')
ax[0].set_ylabel('acceleration along the incline [m/s^2]')
ax[0].set_title('incline 20 degrees, g = 10, no fluid')
ax[0].legend(fontsize=8)
for k, mk in (('block', 'o'), ('blockNotTurning', 'x'), ('blockOnSlab', '+')):
    sel = [r for r in rows if r['body'] == k and r['a_exact'] == 0]
    ax[1].semilogy([r['mu'] for r in sel], [abs(r['U_end']) for r in sel], mk,
                   mfc='none', label=names[k])
sel = [r for r in rows if r['body'] == 'blockNotTurning' and r['a_exact'] == 0]
ax[1].semilogy([r['mu'] for r in sel],
               [g*math.sin(theta)*2*r['dt_sub'] for r in sel], 'k-', lw=1,
               label='g sin(theta) 2 dt_s (rotation off)')
for k, mk in (('block', 'o'), ('blockNotTurning', 'x')):
    sel = [r for r in spring if r['body'] == k and r['a_exact'] == 0]
    ax[1].semilogy([r['mu'] for r in sel], [abs(r['corner_slip']) for r in sel],
                   mk, color='C3', label=names[k] + ', tangentialSpring: slid')
ax[1].set_xlabel('friction coefficient mu (held: mu >= tan(theta) = 0.364)')
ax[1].set_ylabel('speed after 0.5 s [m/s]; slid [m]')
ax[1].set_title('held: velocityRegularised creeps, tangentialSpring holds')
ax[1].legend(fontsize=8)
fig.tight_layout()
fig.savefig(os.path.join(here, 'friction.png'), dpi=110)
print('Written table.md, table-spring.md, friction.png')
