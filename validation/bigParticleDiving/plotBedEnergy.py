#!/usr/bin/python3
"""The bodies' kinetic energy against t for runs of ./Allrun.

Usage: plotBedEnergy.py [-o NAME] RUN [RUN ...]

For each run folder (runs/rho<RHO>-L<level>[-random|-placed][-z<Z>], a
copy of tutorials/fbmFoam/bigParticleDiving) reads

    postProcessing/fbmBodies/*/summary.dat   kineticEnergy of all bodies
                                             (joined over restarts)
    constant/fbmProperties, system/caseParameters   dampingRatio, rhoBig,
                                             level
    constant/smallParticles, <last time>/lagrangian/fbmBodies   the small
                                             disks at the start and at the
                                             last written time

and writes NAME.csv and NAME.png (default bedEnergy) beside this script:

    NAME.csv   one row per run: run, rho, level, zeta (dampingRatio),
               t_end, ke_start (first step), ke_01 and ke_06 (at the first
               steps at or after t = 0.1 and 0.6), decay = ke_06/ke_01,
               ke_max_late (largest after t = 0.5), t_cloud (the last
               written time), rise_mean and rise_max (mean and largest
               change of the small disks' centre heights from the start
               to t_cloud: a bed at rest keeps 0)
    NAME.png   the kinetic energy against t (log scale), one line a run

Made for the bed alone (RHO 1.0: the big disk is neutrally buoyant and
stays where it is, so the energy is the small disks'). The bed is settled
by the contacts alone, so the fluid's start is a transient that a sound
coupling lets decay (decay << 1); where the coupling feeds energy into the
contact oscillations the bed heats up instead. Units as summary.dat (the
case's: g cm^2/s^2 for the mesh's 0.1 cm depth).
Run it with Debian's python3 (/usr/bin/python3, python3-matplotlib).
"""

import csv
import os
import sys

import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, '..', '..', 'bin'))
import fbmOutput  # noqa: E402
from plotResults import dampingRatio  # noqa: E402

import matplotlib  # noqa: E402
matplotlib.use('Agg')
import matplotlib.pyplot as plt  # noqa: E402


def at(t, v, time):
    """v at the first step at or after time (None when not reached)."""
    i = np.searchsorted(t, time - 1e-9)
    return v[i] if i < len(t) else None


def main(argv):
    name = 'bedEnergy'
    if len(argv) >= 2 and argv[0] == '-o':
        name, argv = argv[1], argv[2:]
    if not argv:
        sys.exit(__doc__)
    rows, curves = [], []
    for run in argv:
        s = fbmOutput.summary(run)
        if not s:
            sys.exit('%s: no summary.dat (see %s/log.fbmFoam)' % (run, run))
        params = os.path.join(run, 'system', 'caseParameters')
        t, ke = s['Time'], s['kineticEnergy']
        row = {
            'run': os.path.basename(run.rstrip('/')),
            'rho': float(fbmOutput.dictEntry(params, 'rhoBig')),
            'level': int(fbmOutput.dictEntry(params, 'level')),
            'zeta': dampingRatio(run),
            't_end': t[-1],
            'ke_start': ke[0],
            'ke_01': at(t, ke, 0.1),
            'ke_06': at(t, ke, 0.6),
        }
        if row['ke_01'] and row['ke_06'] is not None:
            row['decay'] = row['ke_06']/row['ke_01']
        late = t > 0.5
        row['ke_max_late'] = ke[late].max() if late.any() else None
        times = fbmOutput.cloudTimes(run)
        if times:
            X, r = fbmOutput.readParticleList(
                os.path.join(run, 'constant', 'smallParticles'))
            c = fbmOutput.readCloud(run, times[-1], fields=('d', 'id'))
            small = c['d'] < 3*r.min()     # the big disk is 8 times larger
            if small.sum() != len(r):
                sys.exit('%s: %d small disks at t = %s, %d in the list'
                         % (run, small.sum(), times[-1], len(r)))
            # the small disks are the bodies after the big one: ids follow
            # the list's order
            dy = c['positions'][small, 1] - X[:, 1]
            row['t_cloud'] = float(times[-1])
            row['rise_mean'] = float(dy.mean())
            row['rise_max'] = float(dy.max())
        rows.append(row)
        curves.append((t, ke))

    cols = ['run', 'rho', 'level', 'zeta', 't_end', 'ke_start', 'ke_01',
            'ke_06', 'decay', 'ke_max_late', 't_cloud', 'rise_mean',
            'rise_max']
    out = os.path.join(here, name + '.csv')
    with open(out, 'w') as f:
        w = csv.writer(f, lineterminator='\n')
        w.writerow(cols)
        for r in rows:
            w.writerow(['' if r.get(c) is None else
                        ('%.6g' % r[c] if isinstance(r[c], float) else r[c])
                        for c in cols])
    print(open(out).read(), end='')

    fig, ax = plt.subplots(figsize=(8, 5))
    for r, (t, ke) in zip(rows, curves):
        ax.semilogy(t, np.maximum(ke, 1e-12), lw=0.8,
                    label='%s: dampingRatio %g, rho_s %g, level %d'
                    % (r['run'], r['zeta'], r['rho'], r['level']))
    ax.set_xlabel('t [s]')
    ax.set_ylabel('kinetic energy of all bodies [g cm^2/s^2]')
    ax.set_title('bigParticleDiving: kinetic energy of the bodies')
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(here, name + '.png'), dpi=120)
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))
