"""Collect the lighter-model runs (runs/<name>[.<k>]) into results.csv and
table.md.

Per run: cells, time steps, CPU time (fbmFoam's ExecutionTime: the last
one, and per step the difference between the last and the first over the
steps between them, which leaves out the start-up), the cost split of the
last "fbm: wall time per step" line (fluid and each body phase, in % of
the step's wall time), the mean and largest number of collision sub-steps
per fluid step, and the case's own accuracy numbers:
- settlingParticle: Re_max = rho_s |U|_max d / mu (mu = rho_f nu = 0.1,
  rho_s = 1.5, d = 0.25), the final x drift and angular velocity;
- DKT: kissing, smallest gap, tumbling (tutorials/fbmFoam/DKT/dkt.py);
- cylinderDFG2D-1: cD and cL at the end;
- settlingParticle level 4 and settlingSphere: the settling speed at the
  end (short runs: for the cost only).
With repeated runs (<name>.<k>) the row of the smallest CPU time per step
is kept and the spread given.
"""
import csv
import glob
import os
import re
import subprocess

here = os.path.dirname(os.path.abspath(__file__))
dktScript = os.path.join(here, '../../tutorials/fbmFoam/DKT/dkt.py')

switches = {
    'spBase': ('settlingParticle L3', 'base: no collisions, rotate yes'),
    'spColl': ('settlingParticle L3', 'collisions block of DKT added'),
    'spNoRot': ('settlingParticle L3', 'rotate no'),
    'dktBase': ('DKT L3', 'base: rotate yes, nStepsPerContact 20'),
    'dktNoRot': ('DKT L3', 'rotate no'),
    'dktN5': ('DKT L3', 'nStepsPerContact 5'),
    'dktN50': ('DKT L3', 'nStepsPerContact 50'),
    'dfgME': ('cylinderDFG2D-1 L2', 'forceModel momentumExchange'),
    'dfgVI': ('cylinderDFG2D-1 L2', 'forceModel volumeIntegral'),
    'sp2D': ('settlingParticle L4, 2D', 'nOuterCorrectors 1, t = 0.15'),
    'sphere3D': ('settlingSphere, 3D', 'nOuterCorrectors 1, t = 0.15'),
}


def bodyRows(run, body):
    files = glob.glob(os.path.join(run, 'postProcessing/fbmBodies/*',
                                   body + '.dat'))
    out = []
    for f in sorted(files, key=lambda p: float(p.split('/')[-2])):
        for line in open(f):
            if not line.startswith('#') and line.strip():
                out.append([float(x) for x in line.split()])
    return out


def collectRun(run):
    name = os.path.basename(run).split('.')[0]
    r = {'name': name, 'run': os.path.basename(run)}
    r['case'], r['switch'] = switches[name]
    log = open(os.path.join(run, 'log.fbmFoam')).read()
    r['exit'] = open(os.path.join(run, 'exitCode')).read().strip() \
        if os.path.exists(os.path.join(run, 'exitCode')) else ''
    m = re.search(r'nCells:\s*(\d+)',
                  open(os.path.join(run, 'log.blockMesh')).read())
    r['cells'] = int(m.group(1)) if m else ''
    steps = len(re.findall(r'^Time = ', log, re.M))
    cpu = [float(x) for x in re.findall(r'^ExecutionTime = ([0-9.eE+-]+) s',
                                        log, re.M)]
    r['steps'] = steps
    r['cpu_s'] = cpu[-1] if cpu else ''
    r['cpu_per_step'] = ((cpu[-1] - cpu[0])/(len(cpu) - 1)
                         if len(cpu) > 1 else '')
    # over the second half of the steps (the developed flow)
    half = len(cpu)//2
    r['cpu_per_step_late'] = ((cpu[-1] - cpu[half])/(len(cpu) - 1 - half)
                              if len(cpu) > 3 else '')
    split = re.findall(r'^fbm: wall time per step over .*$', log, re.M)
    if split:
        line = split[-1]
        r['wall_per_step'] = float(re.search(r'steps: ([0-9.eE+-]+) s',
                                             line).group(1))
        for key, pat in (('fluid', 'fluid'), ('bodies', 'bodies'),
                         ('motion', 'motion/DEM'), ('cellsPhase', 'cells'),
                         ('forcing', 'forcing'), ('forces', 'forces'),
                         ('output', 'output')):
            m = re.search(pat + r' ([0-9.eE+-]+) s \((\d+) %\)', line)
            r[key + '_s'] = float(m.group(1))
            r[key + '_pct'] = int(m.group(2))
    sub = [int(x) for x in re.findall(r'^fbm: collisions: (\d+) sub-steps',
                                      log, re.M)]
    r['subSteps_mean'] = sum(sub)/len(sub) if sub else ''
    r['subSteps_max'] = max(sub) if sub else ''

    if name in ('spBase', 'spColl', 'spNoRot'):
        rows = bodyRows(run, 'particle')
        # Time Fx Fy Fz Tx Ty Tz x y z Ux Uy Uz wx wy wz
        speeds = [(v[10]**2 + v[11]**2)**0.5 for v in rows]
        r['Re_max'] = 1.5*max(speeds)*0.25/0.1
        r['t_end'] = rows[-1][0]
        r['y_end'] = rows[-1][8]
        r['x_drift'] = rows[-1][7] - 1.0
        r['omega_end'] = rows[-1][15]
    elif name in ('sp2D', 'sphere3D'):
        rows = bodyRows(run, 'particle' if name == 'sp2D' else 'sphere')
        r['t_end'] = rows[-1][0]
        r['v_end'] = rows[-1][11]
    elif name.startswith('dkt'):
        out = subprocess.run(['/usr/bin/python3', dktScript, run],
                             capture_output=True, text=True).stdout
        m = re.search(r'kissing \(gap < range\): from t = (\S+) to t = (\S+)',
                      out)
        r['kiss'], r['kissEnd'] = m.group(1), m.group(2)
        m = re.search(r'smallest gap ([0-9.eE+-]+) \(([0-9.]+) h\) at t = '
                      r'([0-9.]+)', out)
        r['gap_min'], r['gap_min_h'], r['t_gap_min'] = m.groups()
        m = re.search(r'tumbling .*: t = (\S+)', out)
        r['tumble'] = m.group(1)
        r['t_end'] = bodyRows(run, 'lower')[-1][0]
    elif name.startswith('dfg'):
        rows = bodyRows(run, 'cylinder')
        # Time Fx Fy Fz Tx Ty Tz Cd Cl ...
        r['cD'] = rows[-1][7]
        r['cL'] = rows[-1][8]
        r['t_end'] = rows[-1][0]
    return r


runs = sorted(d for d in glob.glob(os.path.join(here, 'runs/*'))
              if os.path.isdir(d) and os.path.exists(
                  os.path.join(d, 'log.fbmFoam')))
byName = {}
for run in runs:
    r = collectRun(run)
    byName.setdefault(r['name'], []).append(r)

results = []
for name in switches:
    if name not in byName:
        continue
    rs = byName[name]
    best = min(rs, key=lambda x: x['cpu_per_step']
               if x['cpu_per_step'] != '' else 1e30)
    best['repeats'] = len(rs)
    cps = [x['cpu_per_step'] for x in rs if x['cpu_per_step'] != '']
    best['cpu_per_step_max'] = max(cps) if cps else ''
    # phase times (wall clock, so noisy on a shared machine): all repeats
    for k in ('motion_s', 'forcing_s', 'forces_s'):
        v = [x[k] for x in rs if k in x]
        best[k + '_min'] = min(v) if v else ''
        best[k + '_max'] = max(v) if v else ''
    results.append(best)

keys = []
for r in results:
    for k in r:
        if k not in keys:
            keys.append(k)
with open(os.path.join(here, 'results.csv'), 'w') as f:
    w = csv.DictWriter(f, fieldnames=keys)
    w.writeheader()
    for r in results:
        w.writerow(r)

R = {r['name']: r for r in results}


def pct(a, b):
    return 100*(a - b)/b


def us(r, k):
    """Phase time per step in microseconds, range over the repeats"""
    lo, hi = 1e6*r[k + '_min'], 1e6*r[k + '_max']
    return ('%.3g' % lo) if r['repeats'] == 1 else '%.3g-%.3g' % (lo, hi)


def g(x, fmt='%.4g'):
    return fmt % x if isinstance(x, float) else str(x)


with open(os.path.join(here, 'table.md'), 'w') as f:
    f.write('Generated by collect.py from runs/ (CPU: fbmFoam\'s '
            'ExecutionTime; per step: from the first to the last step, '
            'start-up left out; with repeats the smallest; shares from the '
            'last "fbm: wall time per step" line).\n\n')

    f.write('| run | case | switch | cells | steps | CPU s | CPU/step ms '
            '(max of repeats) | fluid % | bodies %: motion/DEM, cells, '
            'forcing, forces, output | sub-steps per step (max) |\n'
            '|---|---|---|---|---|---|---|---|---|---|\n')
    for r in results:
        cpsMax = r.get('cpu_per_step_max', '')
        f.write('| %s | %s | %s | %s | %s | %s | %.2f (%s) | %s | %s: %s, %s, '
                '%s, %s, %s | %s |\n'
                % (r['name'], r['case'], r['switch'], r['cells'], r['steps'],
                   g(r['cpu_s']), 1e3*r['cpu_per_step'],
                   ('%.2f' % (1e3*cpsMax)) if r['repeats'] > 1 else '-',
                   r.get('fluid_pct', ''), r.get('bodies_pct', ''),
                   r.get('motion_pct', ''), r.get('cellsPhase_pct', ''),
                   r.get('forcing_pct', ''), r.get('forces_pct', ''),
                   r.get('output_pct', ''),
                   ('%.1f (%d)' % (r['subSteps_mean'], r['subSteps_max']))
                   if r['subSteps_mean'] != '' else '-'))

    if 'spBase' in R:
        f.write('\n## settlingParticle L3, t = 0.4\n\n| run | CPU/step ms '
                '| vs base | motion/DEM us per step | Re_max | vs base | '
                'x drift | omega end | y end |\n|---|---|---|---|---|---|---|'
                '---|---|\n')
        b = R['spBase']
        for n in ('spBase', 'spColl', 'spNoRot'):
            if n not in R:
                continue
            r = R[n]
            f.write('| %s | %.2f | %+.1f %% | %s | %.4f | %+.3f %% | %.3g '
                    '| %.3g | %.4f |\n'
                    % (n, 1e3*r['cpu_per_step'],
                       pct(r['cpu_per_step'], b['cpu_per_step']),
                       us(r, 'motion_s'), r['Re_max'],
                       pct(r['Re_max'], b['Re_max']), r['x_drift'],
                       r['omega_end'], r['y_end']))

    if 'dktBase' in R:
        f.write('\n## DKT L3, t = 3\n\n| run | CPU s | CPU/step ms | vs base '
                '| motion/DEM us per step | sub-steps per step | kissing '
                '| smallest gap (h) at t | tumbling |\n'
                '|---|---|---|---|---|---|---|---|---|\n')
        b = R['dktBase']
        for n in ('dktBase', 'dktNoRot', 'dktN5', 'dktN50'):
            if n not in R:
                continue
            r = R[n]
            f.write('| %s | %.1f | %.2f | %+.1f %% | %s | %.1f | %s - %s '
                    '| %s (%s h) at %s | %s |\n'
                    % (n, r['cpu_s'], 1e3*r['cpu_per_step'],
                       pct(r['cpu_per_step'], b['cpu_per_step']),
                       us(r, 'motion_s'), r['subSteps_mean'], r['kiss'],
                       r['kissEnd'], r['gap_min'], r['gap_min_h'],
                       r['t_gap_min'], r['tumble']))

    if 'dfgME' in R:
        f.write('\n## cylinderDFG2D-1 L2, t = 10 (reference cD 5.579535)\n\n'
                '| run | cD | cL | CPU/step ms | forces us per step (% of '
                'the step\'s wall time) | forcing us per step |\n'
                '|---|---|---|---|---|---|\n')
        for n in ('dfgME', 'dfgVI'):
            if n not in R:
                continue
            r = R[n]
            f.write('| %s | %.5f | %.5f | %.2f | %s (%d %%) | %s |\n'
                    % (n, r['cD'], r['cL'], 1e3*r['cpu_per_step'],
                       us(r, 'forces_s'), r['forces_pct'],
                       us(r, 'forcing_s')))

    if 'sp2D' in R and 'sphere3D' in R:
        f.write('\n## 2D against 3D (one outer corrector each, t = 0.15; '
                'CPU per step over the second half of the steps)\n\n'
                '| run | cells | R/h | cells per particle area/volume | '
                'CPU/step ms | CPU/step per 1000 cells ms | bodies % |\n'
                '|---|---|---|---|---|---|---|\n')
        import math
        for n, Rh, cellsIn in (
                ('sp2D', 6, math.pi*6**2),
                ('sphere3D', 4, 4/3*math.pi*4**3)):
            r = R[n]
            f.write('| %s | %d | %d | %.0f | %.2f | %.3f | %s |\n'
                    % (n, r['cells'], Rh, cellsIn, 1e3*r['cpu_per_step_late'],
                       1e6*r['cpu_per_step_late']/r['cells'],
                       r['bodies_pct']))

print('wrote results.csv, table.md')
