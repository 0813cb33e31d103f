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
