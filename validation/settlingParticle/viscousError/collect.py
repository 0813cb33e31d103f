"""results.csv of the runs of Allrun (the error of semiImplicit in the
viscous number of its step): per run the coupling, maxViscousRatio, the
PISO correctors, the smoothed and the raw maximum speed while the gap to
the bottom wall is at least 2 d (as Re = rho_s U d/mu), the steps, the
steps the coupling's limit set, the CPU time and the oscillation index of
the speed over the last 50 steps of that window. A run not under runs/
keeps its row of the existing results.csv."""
import csv
import glob
import math
import os
import re

import numpy as np

RHO_S, D, NU, R = 1.5, 0.25, 0.3, 0.125
COLUMNS = ["run", "coupling", "maxViscousRatio", "nCorrectors", "consistent",
           "Re_smooth", "Re_raw", "steps", "limited", "cpu_s", "osc_pct"]

rows = {}
if os.path.exists("results.csv"):
    rows = {r["run"]: r for r in csv.DictReader(open("results.csv"))}
for run in sorted(glob.glob("runs/*")):
    name = os.path.basename(run)
    if not re.match(r"(SB|Bc|B)-r", name):
        continue
    dat = os.path.join(run, "postProcessing/fbmBodies/0/particle.dat")
    log = os.path.join(run, "log.fbmFoam")
    if not os.path.exists(dat) or not os.path.exists(log):
        continue
    d = np.array([[float(v) for v in l.split()] for l in open(dat)
                  if not l.startswith("#")])
    t, y, u = d[:, 0], d[:, 8], np.hypot(d[:, 10], d[:, 11])
    keep = (y - R) >= 2*D
    t, u = t[keep], u[keep]
    smooth = np.array([u[(t >= ti - 0.01) & (t <= ti + 0.01)].mean()
                       for ti in t])
    w = u[-50:]
    dev = w[1:-1] - 0.5*(w[:-2] + w[2:])
    text = open(log).read()
    cpu = re.findall(r"^ExecutionTime = (\S+)", text, re.M)
    fvs = open(os.path.join(run, "system/fvSolution")).read()
    m = re.match(r"(SB|Bc|B)-r([0-9.]+)(?:-n(\d+))?$", name)
    rows[name] = {
        "run": name,
        "coupling": "semiImplicit" if m.group(1) == "SB" else "explicit",
        "maxViscousRatio": m.group(2),
        "nCorrectors": re.search(r"^\s*nCorrectors\s+(\d+);", fvs, re.M).group(1),
        "consistent": "yes" if re.search(r"^\s*consistent\s+yes;", fvs, re.M)
                      else "no",
        "Re_smooth": "%.4f" % (RHO_S*smooth.max()*D/NU),
        "Re_raw": "%.4f" % (RHO_S*u.max()*D/NU),
        "steps": len(re.findall(r"^Time = ", text, re.M)),
        "limited": len(re.findall(r"^deltaT = \S+ \(coupling", text, re.M)),
        "cpu_s": cpu[-1] if cpu else "",
        "osc_pct": "%.3f" % (100*math.sqrt((dev**2).mean())/w.mean()),
    }
with open("results.csv", "w", newline="") as f:
    w = csv.DictWriter(f, fieldnames=COLUMNS)
    w.writeheader()
    for name in sorted(rows, key=lambda n: (n[:2] != "SB", n)):
        w.writerow({c: rows[name][c] for c in COLUMNS})
print(open("results.csv").read())


def keep(path, key):
    """The rows of an existing csv by their first column"""
    if not os.path.exists(path):
        return {}
    return {r[key]: r for r in csv.DictReader(open(path))}


# The settling disk as the tutorial runs it, with 2, 3 or 4 correctors
disk = keep("disk4.csv", "run")
for run in sorted(glob.glob("runs/disk4-n*")):
    name = os.path.basename(run)
    dat = os.path.join(run, "postProcessing/fbmBodies/0/particle.dat")
    log = os.path.join(run, "log.fbmFoam")
    if not os.path.exists(dat) or not os.path.exists(log):
        continue
    d = np.array([[float(v) for v in l.split()] for l in open(dat)
                  if not l.startswith("#")])
    y, u = d[:, 8], np.hypot(d[:, 10], d[:, 11])
    u = u[(y - R) >= 2*D]
    cpu = re.findall(r"^ExecutionTime = (\S+)", open(log).read(), re.M)
    disk[name] = {"run": name, "nCorrectors": name.split("-n")[1],
                  "Re_max": "%.4f" % (RHO_S*u.max()*D/0.1),
                  "cpu_s": cpu[-1] if cpu else ""}
if disk:
    with open("disk4.csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=["run", "nCorrectors", "Re_max",
                                          "cpu_s"])
        w.writeheader()
        for name in sorted(disk):
            w.writerow(disk[name])
    print(open("disk4.csv").read())

# The resting bed: the disks' kinetic energy at t = 0.1 and 0.6
import sys  # noqa: E402
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "../../../bin"))
import fbmOutput  # noqa: E402

bed = keep("bed.csv", "run")
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
    cpu = re.findall(r"^ExecutionTime = (\S+)",
                     open(os.path.join(run, "log.fbmFoam")).read(), re.M)
    bed[name] = {"run": name,
                 "scheme": "backward" if name.startswith("bed-B") else "Euler",
                 "nCorrectors": name.split("-n")[1],
                 "ke_0.1": "%.4g" % at(0.1), "ke_0.6": "%.4g" % at(0.6),
                 "ratio": "%.4g" % (at(0.6)/at(0.1)),
                 "cpu_s": cpu[-1] if cpu else ""}
if bed:
    with open("bed.csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=["run", "scheme", "nCorrectors",
                                          "ke_0.1", "ke_0.6", "ratio",
                                          "cpu_s"])
        w.writeheader()
        for name in sorted(bed):
            w.writerow(bed[name])
    print(open("bed.csv").read())
