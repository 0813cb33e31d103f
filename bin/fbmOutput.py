#!/usr/bin/python3
"""Read fbmFoam's body output: histories, summary.dat and the fbmBodies cloud.

A module for the validation scripts (import it after putting bin/ on
sys.path); run as a script it prints what a case holds:

    fbmOutput.py CASE

Histories: postProcessing/fbmBodies/<startTime>/<name>.dat (a body's
columns Time Fx Fy Fz Tx Ty Tz x y z Ux Uy Uz wx wy wz, or summary.dat
with Time N maxSpeed kineticEnergy Xx Xy Xz minPairGap minWallGap), named
by the '#' header line that starts with '# Time'. A restart opens a new
<startTime> folder: the folders are joined in time order and the rows of an
earlier folder after a later folder's start time are dropped (the
restarted run wrote them again).

Cloud: <time>/lagrangian/fbmBodies/{positions,d,U,id,...} in the case
folder, or in processor*/<time>/... when the case folder has none (a
decomposed run not reconstructed). fbmFoam writes them in ASCII, one value a
line; reconstructPar writes them again in the case's writeFormat (binary
or ASCII, a uniform list as N{value}): all of these are read.

Use Debian's /usr/bin/python3 (numpy).
"""

import glob
import os
import re
import sys

import numpy as np

GREAT = 1e15        # fbmFoam's "no pair or wall within reach" gap


# * * * * * * * * * * * * * * * * Histories * * * * * * * * * * * * * * * * #

def _startTime(path):
    return float(os.path.basename(os.path.dirname(path)))


def history(case, name):
    """Columns of postProcessing/fbmBodies/*/<name>.dat joined over restarts.

    Returns a dict column name -> numpy array (empty dict without files).
    """
    files = sorted(glob.glob(os.path.join(
        case, 'postProcessing', 'fbmBodies', '*', name + '.dat')),
        key=_startTime)
    columns = None
    rows = []
    for f in files:
        start = _startTime(f)
        # the restarted run rewrites everything after its start time (the
        # folder name has timePrecision digits: a tolerance far below a
        # time step)
        tol = 1e-6*max(1.0, abs(start))
        rows = [r for r in rows if r[0] <= start + tol]
        with open(f) as fh:
            for line in fh:
                if line.startswith('#'):
                    words = line[1:].split()
                    if words and words[0] == 'Time':
                        if columns is not None and words != columns:
                            raise ValueError('%s: columns %s differ from %s'
                                             % (f, words, columns))
                        columns = words
                    continue
                v = line.split()
                if v:
                    rows.append([float(x) for x in v])
    if not rows:
        return {}
    if columns is None:
        raise ValueError('%s: no "# Time ..." header line' % files[0])
    n = len(columns)
    rows = [r for r in rows if len(r) == n]   # a line cut by a kill
    data = np.array(rows)
    return {c: data[:, i] for i, c in enumerate(columns)}


def bodyRecord(case, name):
    """One body's record postProcessing/fbmBodies/0/<name>.dat as rows of
    floats (Time Fx Fy Fz Tx Ty Tz x y z Ux Uy Uz wx wy wz), its times and
    its speed |U| at each row (a run without restarts; see history for
    joined restarts)."""
    rows = [[float(x) for x in l.split()]
            for l in open(os.path.join(case, 'postProcessing', 'fbmBodies',
                                       '0', name + '.dat'))
            if not l.startswith('#')]
    t = [r[0] for r in rows]
    speed = [(r[10]**2 + r[11]**2 + r[12]**2)**0.5 for r in rows]
    return rows, t, speed


def largestBodyCourant(t, speed, h):
    """Largest |U| dt/h over a record (dt the step to each row)."""
    return max(speed[i]*(t[i] - (t[i - 1] if i else 0.0))/h
               for i in range(len(t)))


def speedAt(t, speed, time):
    """The speed at the last row at or before time, '%.5g'-formatted, or ''
    when the record ends before time."""
    s = [v for ti, v in zip(t, speed) if ti <= time + 1e-9]
    return '%.5g' % s[-1] if s and t[-1] >= time - 1e-9 else ''


def summary(case):
    """summary.dat joined over restarts (see history)."""
    return history(case, 'summary')


def largestOverlap(s):
    """Smallest pair and wall gaps over a summary and their times.

    Returns (minPairGap, tPair, minWallGap, tWall); a gap is None when no
    pair (wall) was ever within reach (GREAT in every row).
    """
    out = []
    for key in ('minPairGap', 'minWallGap'):
        g = s[key]
        ok = g < 0.1*GREAT
        if not ok.any():
            out += [None, None]
        else:
            i = np.argmin(np.where(ok, g, np.inf))
            out += [float(g[i]), float(s['Time'][i])]
    return tuple(out)


# * * * * * * * * * * * * * * * * * Logs * * * * * * * * * * * * * * * * * * #

def cpuTime(log):
    """fbmFoam's CPU time: the last 'ExecutionTime = X s' of a log."""
    t = None
    try:
        with open(log) as fh:
            for line in fh:
                m = re.match(r'^ExecutionTime = ([0-9.eE+-]+) s', line)
                if m:
                    t = float(m.group(1))
    except OSError:
        pass
    return t


def blockMeshInfo(case):
    """(cells, ((xmin, ymin, zmin), (xmax, ymax, zmax))) from log.blockMesh.

    Either is None when the log lacks it.
    """
    cells = box = None
    try:
        text = open(os.path.join(case, 'log.blockMesh')).read()
    except OSError:
        return None, None
    m = re.search(r'^\s*nCells:\s*(\d+)', text, re.M)
    if m:
        cells = int(m.group(1))
    m = re.search(r'boundingBox:\s*\(([^)]*)\)\s*\(([^)]*)\)', text)
    if m:
        box = (tuple(float(x) for x in m.group(1).split()),
               tuple(float(x) for x in m.group(2).split()))
    return cells, box


def dictEntry(path, key):
    """The value of a top-level 'key value;' line of a dictionary file."""
    text = open(path).read()
    m = re.search(r'^' + re.escape(key) + r'\s+([^;]*);', text, re.M)
    return m.group(1).strip() if m else None


# * * * * * * * * * * * * * * * * * Cloud * * * * * * * * * * * * * * * * * #

def _isTime(name):
    try:
        float(name)
        return True
    except ValueError:
        return False


def cloudTimes(case, cloud='fbmBodies'):
    """Times (names and values, ascending) that hold the cloud's positions."""
    names = set()
    for root in [case] + glob.glob(os.path.join(case, 'processor*')):
        for d in os.listdir(root):
            if _isTime(d) and os.path.isfile(
                    os.path.join(root, d, 'lagrangian', cloud, 'positions')):
                names.add(d)
    return sorted(names, key=float)


def _header(data):
    """(format, label bytes, offset after the FoamFile header)."""
    m = re.search(rb'FoamFile\s*\{(.*?)\}', data, re.S)
    if not m:
        raise ValueError('no FoamFile header')
    head = m.group(1)
    fmt = re.search(rb'format\s+(\w+)\s*;', head)
    fmt = fmt.group(1).decode() if fmt else 'ascii'
    arch = re.search(rb'label=(\d+)', head)
    labelBytes = int(arch.group(1))//8 if arch else 4
    return fmt, labelBytes, m.end()


def _skipToSize(data, pos):
    """Position and value of the list size, skipping comments."""
    while True:
        m = re.compile(rb'\s*').match(data, pos)
        pos = m.end()
        if data.startswith(b'//', pos):
            pos = data.index(b'\n', pos) + 1
        elif data.startswith(b'/*', pos):
            pos = data.index(b'*/', pos) + 2
        else:
            break
    m = re.compile(rb'(\d+)\s*').match(data, pos)
    if not m:
        raise ValueError('no list size at byte %d' % pos)
    return m.end(), int(m.group(1))


def readCloudFile(path, kind):
    """A cloud file as a numpy array.

    kind: 'scalar', 'label', 'vector' or 'positions' (x y z and cell; the
    cells are dropped).
    """
    data = open(path, 'rb').read()
    fmt, labelBytes, pos = _header(data)
    pos, n = _skipToSize(data, pos)
    ncomp = 3 if kind in ('vector', 'positions') else 1
    shape = (n, 3) if ncomp == 3 else (n,)
    dtype = {'scalar': float, 'vector': float, 'positions': float,
             'label': int}[kind]
    if n == 0:
        return np.zeros(shape, dtype=dtype)
    lead = data[pos:pos + 1]
    if lead == b'{':                    # uniform list N{value}
        end = data.index(b'}', pos)
        v = [float(x) for x in
             data[pos + 1:end].decode().replace('(', ' ').replace(')', ' ')
             .split()]
        return np.tile(np.array(v, dtype=dtype), (n, 1)).reshape(shape)
    if lead != b'(':
        raise ValueError('%s: expected ( or { at byte %d' % (path, pos))
    pos += 1
    if fmt == 'binary' and kind != 'positions':
        if kind == 'label':
            dt = np.dtype('<i%d' % labelBytes)
        else:
            dt = np.dtype('<f8')
        a = np.frombuffer(data, dtype=dt, count=n*ncomp, offset=pos)
        return a.astype(dtype).reshape(shape)
    if fmt == 'binary':
        # IOPosition: a newline, then per particle particle::writePosition's
        # block '(' position (3 doubles) cell ')' and a newline
        pos = re.compile(rb'\s*').match(data, pos).end()
        rec = 1 + 24 + labelBytes + 1 + 1
        raw = np.frombuffer(data, dtype=np.uint8, count=n*rec, offset=pos)
        raw = raw.reshape(n, rec)
        if (raw[:, 0] != ord('(')).any() or (raw[:, -2] != ord(')')).any():
            raise ValueError('%s: binary positions not understood' % path)
        return raw[:, 1:25].copy().view('<f8').reshape(n, 3)
    # ASCII: numbers, brackets dropped
    end = data.rindex(b')')
    words = data[pos:end].replace(b'(', b' ').replace(b')', b' ').split()
    if kind == 'positions':
        a = np.array(words, dtype=float).reshape(n, 4)[:, :3]
    else:
        a = np.array(words, dtype=float).reshape(shape)
    return a.astype(dtype)


_kinds = {'positions': 'positions', 'd': 'scalar', 'rho': 'scalar',
          'id': 'label', 'U': 'vector', 'omega': 'vector', 'F': 'vector'}


def readCloud(case, time, fields=('d', 'U', 'id'), cloud='fbmBodies'):
    """The cloud at a time name: dict of 'positions' and the fields.

    From the case folder, or joined over processor*/ when the case folder
    lacks it. Sorted by id when id is read.
    """
    roots = [case]
    if not os.path.isfile(os.path.join(case, time, 'lagrangian', cloud,
                                       'positions')):
        roots = sorted(glob.glob(os.path.join(case, 'processor*')),
                       key=lambda p: int(re.sub(r'\D', '', p) or 0))
    out = {}
    for name in ('positions',) + tuple(fields):
        parts = []
        for root in roots:
            path = os.path.join(root, time, 'lagrangian', cloud, name)
            if os.path.isfile(path):
                parts.append(readCloudFile(path, _kinds[name]))
            elif os.path.isfile(os.path.join(root, time, 'lagrangian', cloud,
                                              'positions')):
                raise IOError('missing ' + path)
        if not parts:
            raise IOError('no cloud %s at time %s in %s' % (cloud, time, case))
        out[name] = np.concatenate(parts)
    if 'id' in out:
        order = np.argsort(out['id'], kind='stable')
        out = {k: v[order] for k, v in out.items()}
    return out


def readParticleList(path):
    """Centres and radii of a fbmSetParticles list file.

    The file holds 'particles [N] ( (x y z) radius [rho] ... );'. Returns
    (centres (N, 3), radii (N,)).
    """
    text = open(path).read()
    text = re.sub(r'/\*.*?\*/', ' ', text, flags=re.S)
    text = re.sub(r'//[^\n]*', ' ', text)
    m = re.search(r'\bparticles\s*(\d+\s*)?\((.*)\)\s*;', text, re.S)
    if not m:
        raise ValueError('%s: no particles [N] ( ... );' % path)
    body = m.group(2)
    centres, radii = [], []
    # each entry: (x y z) radius [rho]
    for e in re.finditer(r'\(\s*([^()]*?)\s*\)\s*([0-9.eE+-]+)'
                         r'(?:\s+([0-9.eE+-]+))?', body):
        centres.append([float(x) for x in e.group(1).split()])
        radii.append(float(e.group(2)))
    return np.array(centres), np.array(radii)


# * * * * * * * * * * * * * * * * * Main * * * * * * * * * * * * * * * * * * #

if __name__ == '__main__':
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    case = sys.argv[1]
    s = summary(case)
    if s:
        print('summary.dat: %d rows, t = %g to %g, N = %d'
              % (len(s['Time']), s['Time'][0], s['Time'][-1], s['N'][-1]))
        print('smallest pair gap %s at t = %s, wall gap %s at t = %s'
              % largestOverlap(s))
    times = cloudTimes(case)
    print('cloud times:', ' '.join(times))
    if times:
        c = readCloud(case, times[-1])
        print('t = %s: %d bodies, d from %g to %g, largest |U| %g'
              % (times[-1], len(c['d']), c['d'].min(), c['d'].max(),
                 np.sqrt((c['U']**2).sum(axis=1)).max()))
    print('fbmFoam CPU time:', cpuTime(os.path.join(case, 'log.fbmFoam')))
