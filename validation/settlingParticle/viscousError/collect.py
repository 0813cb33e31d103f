"""The tables of the runs of Allrun (the error of semiImplicit in the
viscous number of its step):
- results.csv (runs SB-*, B-*, Bc-*): per run the coupling, its impulse
  (semiImplicit's; a run name ending in -s: solved), its bodyScheme (a
  run name ending in -f: fluid, else Euler), maxViscousRatio, the
  PISO correctors, the smoothed and the raw maximum
  speed while the gap to the bottom wall is at least 2 d (as
  Re = rho_s U d/mu), the steps, the steps the coupling's limit set, the
  CPU time and the oscillation index of the speed over the last 50 steps
  of that window;
- disk4.csv (runs disk4-n*): the impulse, the bodyScheme, Re_max and the
  CPU time;
- bed.csv (runs bed-*): the impulse, the bodyScheme, the disks' kinetic energy at t = 0.1
  and 0.6 and their ratio.
A run not under runs/ keeps its row of the existing file."""
import csv
import glob
import math
import os
import re
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "../../../bin"))
import fbmOutput  # noqa: E402

RHO_S, D, NU, R = 1.5, 0.25, 0.3, 0.125
COLUMNS = ["run", "coupling", "impulse", "bodyScheme", "maxViscousRatio", "nCorrectors", "consistent",
           "Re_smooth", "Re_raw", "steps", "limited", "cpu_s", "osc_pct"]


def keep(path):
    """The rows of an existing csv by their run"""
    if not os.path.exists(path):
        return {}
    rows = {r["run"]: r for r in csv.DictReader(open(path))}
    for r in rows.values():                 # rows from before the column
        r.setdefault("impulse", impulse(r["run"]))
        r.setdefault("bodyScheme", bodyScheme(r["run"]))
    return rows


def impulse(name):
    """semiImplicit's impulse of a run: solved for a name ending in -s,
    none for the explicit coupling's runs (B-*, Bc-*)"""
    if re.match(r"Bc?-", name):
        return ""
    return "solved" if re.sub(r"-f$", "", name).endswith("-s") else "final"


def bodyScheme(name):
    """semiImplicit's bodyScheme of a run: fluid for a name ending in -f,
    Euler for the others (and Euler's time scheme, bed-E-*, where the two
    are the same), none for the explicit coupling's runs"""
    if re.match(r"Bc?-", name):
        return ""
    return "fluid" if name.endswith("-f") else "Euler"


def write(path, columns, rows, key=None):
    """Write rows (a dict by run) in the order of key, and print the file"""
    if not rows:
        return
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=columns)
        w.writeheader()
        for name in sorted(rows, key=key):
            w.writerow({c: rows[name][c] for c in columns})
    print(open(path).read())


def lastCpu(text):
    """The last ExecutionTime of a solver log ('' if none)"""
    cpu = re.findall(r"^ExecutionTime = (\S+)", text, re.M)
    return cpu[-1] if cpu else ""


def fall(run):
    """(t, |U|, log text) of the disk while the gap to the bottom wall is
    at least 2 d, or None when the run has no record or log"""
    dat = os.path.join(run, "postProcessing/fbmBodies/0/particle.dat")
    log = os.path.join(run, "log.fbmFoam")
    if not os.path.exists(dat) or not os.path.exists(log):
        return None
    d = np.array([[float(v) for v in l.split()] for l in open(dat)
                  if not l.startswith("#")])
    t, y, u = d[:, 0], d[:, 8], np.hypot(d[:, 10], d[:, 11])
    inWindow = (y - R) >= 2*D
    return t[inWindow], u[inWindow], open(log).read()


# The step set by the viscous limit's ratio
rows = keep("results.csv")
for run in sorted(glob.glob("runs/*")):
    name = os.path.basename(run)
    m = re.match(r"(SB|Bc|B)-r([0-9.]+)(?:-n(\d+))?(?:-s)?(?:-f)?$", name)
    record = fall(run) if m else None
    if record is None:
        continue
    t, u, text = record
    smooth = np.array([u[(t >= ti - 0.01) & (t <= ti + 0.01)].mean()
                       for ti in t])
    w = u[-50:]
    dev = w[1:-1] - 0.5*(w[:-2] + w[2:])
    fvs = open(os.path.join(run, "system/fvSolution")).read()
    rows[name] = {
        "run": name,
        "coupling": "semiImplicit" if m.group(1) == "SB" else "explicit",
        "impulse": impulse(name) if m.group(1) == "SB" else "",
        "bodyScheme": bodyScheme(name),
        "maxViscousRatio": m.group(2),
        "nCorrectors": re.search(r"^\s*nCorrectors\s+(\d+);", fvs, re.M).group(1),
        "consistent": "yes" if re.search(r"^\s*consistent\s+yes;", fvs, re.M)
                      else "no",
        "Re_smooth": "%.4f" % (RHO_S*smooth.max()*D/NU),
        "Re_raw": "%.4f" % (RHO_S*u.max()*D/NU),
        "steps": len(re.findall(r"^Time = ", text, re.M)),
        "limited": len(re.findall(r"^deltaT = \S+ \(coupling", text, re.M)),
        "cpu_s": lastCpu(text),
        "osc_pct": "%.3f" % (100*math.sqrt((dev**2).mean())/w.mean()),
    }
write("results.csv", COLUMNS, rows,
      key=lambda n: (n[:2] != "SB", n.endswith("-s"), n))

# The settling disk as the tutorial runs it (nu 0.1), with 2, 3 or 4
# correctors
disk = keep("disk4.csv")
for run in sorted(glob.glob("runs/disk4-n*")):
    record = fall(run)
    if record is None:
        continue
    name = os.path.basename(run)
    _, u, text = record
    disk[name] = {"run": name, "impulse": impulse(name),
                  "bodyScheme": bodyScheme(name),
                  "nCorrectors": re.search(r"-n(\d+)", name).group(1),
                  "Re_max": "%.4f" % (RHO_S*u.max()*D/0.1),
                  "cpu_s": lastCpu(text)}
write("disk4.csv", ["run", "impulse", "bodyScheme", "nCorrectors", "Re_max", "cpu_s"], disk)

# The resting bed: the disks' kinetic energy at t = 0.1 and 0.6
bed = keep("bed.csv")
for run in sorted(glob.glob("runs/bed-*")):
    name = os.path.basename(run)
    try:
        s = fbmOutput.summary(run)
    except Exception as err:                # no record: not run to the end
        print("%s: skipped (%s)" % (name, err), file=sys.stderr)
        continue
    t, ke = s["Time"], s["kineticEnergy"]
    if t[-1] < 0.6 - 1e-9:
        continue
    at = lambda x: ke[np.argmax(t >= x - 1e-9)]
    bed[name] = {"run": name,
                 "scheme": "backward" if name.startswith("bed-B") else "Euler",
                 "impulse": impulse(name),
                 "bodyScheme": bodyScheme(name),
                 "nCorrectors": re.search(r"-n(\d+)", name).group(1),
                 "ke_0.1": "%.4g" % at(0.1), "ke_0.6": "%.4g" % at(0.6),
                 "ratio": "%.4g" % (at(0.6)/at(0.1)),
                 "cpu_s": lastCpu(open(os.path.join(run, "log.fbmFoam")).read())}
write("bed.csv", ["run", "scheme", "impulse", "bodyScheme", "nCorrectors", "ke_0.1", "ke_0.6", "ratio",
                  "cpu_s"], bed)
