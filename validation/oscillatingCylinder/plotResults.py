#!/usr/bin/python3
"""Analyse the oscillating-cylinder runs in runs/ (see Allrun).

For each run, over the third period (10 <= t <= 15): the in-line force per
unit length F(t) (the runs' depth is 0.1), its amplitude (max - min)/2, the
rms of its difference from the finest body-fitted run (interpolated on the
same times) relative to that run's amplitude, and Morison's coefficients
fitted by least squares,
    F = -1/2 rho D Cd U|U| - rho pi D^2/4 Ci dU/dt,
with the cylinder's velocity U = -Umax cos(2 pi f t) (Umax = 1, f = 0.2,
D = 1, rho = 1). CPU: the solver's last ExecutionTime. Writes results.csv,
table.md, force.png and accuracy.png.
"""
import glob
import math
import os
import re

import numpy as np

depth, D, f, Umax = 0.1, 1.0, 0.2, 1.0
t0, t1 = 10.0, 15.0


def load(run):
    c = os.path.join("runs", run)
    if run.startswith("fbm"):
        d = np.loadtxt(os.path.join(c, "postProcessing/fbmBodies/0/cylinder.dat"),
                       comments="#", usecols=(0, 1))
        t, F = d[:, 0], d[:, 1]
        log = os.path.join(c, "log.fbmFoam")
    else:
        t, F = [], []
        for line in open(os.path.join(c, "postProcessing/forces/0/force.dat")):
            if line.startswith("#"):
                continue
            nums = re.findall(r"[-+0-9.eE]+", line)
            t.append(float(nums[0]))
            F.append(float(nums[1]))
        t, F = np.array(t), np.array(F)
        log = os.path.join(c, "log.pimpleFoam")
    cpu = float(re.findall(r"ExecutionTime = ([0-9.eE+-]+) s",
                           open(log).read())[-1])
    nCells = int(re.search(r"nCells:\s*(\d+)",
                           open(os.path.join(c, "log.blockMesh")).read()).group(1))
    return t, F/depth, cpu, nCells


def morison(t, F):
    w = 2*math.pi*f
    U = -Umax*np.cos(w*t)
    dU = Umax*w*np.sin(w*t)
    A = np.column_stack((-0.5*D*U*np.abs(U), -math.pi*D**2/4*dU))
    (Cd, Ci), *_ = np.linalg.lstsq(A, F, rcond=None)
    return Cd, Ci


runs = sorted(os.path.basename(p) for p in glob.glob("runs/*-L*")
              if glob.glob(p + "/postProcessing/*/0/*.dat"))
data = {r: load(r) for r in runs}
refs = sorted(r for r in runs if r.startswith("bodyFitted"))
ref = refs[-1] if refs else None

rows = []
for r in runs:
    t, F, cpu, n = data[r]
    m = (t >= t0 - 1e-9) & (t <= t1 + 1e-9)
    amp = 0.5*(F[m].max() - F[m].min())
    Cd, Ci = morison(t[m], F[m])
    row = dict(run=r, method=r.split("-")[0], level=int(r[-1]), cells=n,
               steps=len(t), cpu_s=cpu, amplitude=amp, Cd=Cd, Ci=Ci)
    if ref:
        tr, Fr, _, _ = data[ref]
        mr = (tr >= t0 - 1e-9) & (tr <= t1 + 1e-9)
        ampRef = 0.5*(Fr[mr].max() - Fr[mr].min())
        Fi = np.interp(t[m], tr, Fr)
        row["ampError_pct"] = 100*(amp/ampRef - 1)
        row["rmsError_pct"] = 100*math.sqrt(np.mean((F[m] - Fi)**2))/ampRef
    rows.append(row)

cols = ["run", "method", "level", "cells", "steps", "cpu_s", "amplitude",
        "Cd", "Ci", "ampError_pct", "rmsError_pct"]
with open("results.csv", "w") as out:
    out.write(",".join(cols) + "\n")
    for row in rows:
        out.write(",".join(
            ("%.5g" % row[c]) if isinstance(row.get(c), float) else str(row.get(c, ""))
            for c in cols) + "\n")

with open("table.md", "w") as out:
    out.write("In-line force per unit length over the third period "
              "(10 <= t <= 15); errors against %s\n\n" % ref)
    out.write("| run | cells | steps | CPU s | amplitude | Cd | Ci | "
              "amplitude error | rms error |\n|---|---|---|---|---|---|---|---|---|\n")
    for row in rows:
        out.write("| %s | %d | %d | %.0f | %.4f | %.3f | %.3f | %s | %s |\n" % (
            row["run"], row["cells"], row["steps"], row["cpu_s"],
            row["amplitude"], row["Cd"], row["Ci"],
            "%+.2f %%" % row["ampError_pct"] if "ampError_pct" in row else "",
            "%.2f %%" % row["rmsError_pct"] if "rmsError_pct" in row else ""))
print(open("table.md").read())

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

fig, ax = plt.subplots(figsize=(7, 4))
for r in runs:
    t, F, _, _ = data[r]
    m = t >= t0 - 1e-9
    ax.plot((t[m] - t0)/5, F[m], "-" if r.startswith("bodyFitted") else "--",
            label=r)
ax.set_xlabel("t/T - 2 (third period)")
ax.set_ylabel("in-line force F_x per unit length")
ax.legend()
ax.grid(alpha=0.3)
fig.tight_layout()
fig.savefig("force.png", dpi=110)

if ref:
    fig, ax = plt.subplots(figsize=(5, 4))
    for method, mk in (("fbm", "o-"), ("bodyFitted", "s-")):
        rr = [row for row in rows if row["method"] == method and row["run"] != ref]
        if rr:
            ax.loglog([row["cpu_s"] for row in rr],
                      [max(abs(row["rmsError_pct"]), 1e-3) for row in rr], mk,
                      label=method + " (levels %s)" % ",".join(str(row["level"]) for row in rr))
    ax.set_xlabel("CPU s (three periods)")
    ax.set_ylabel("rms force error vs %s [%% of amplitude]" % ref)
    ax.legend()
    ax.grid(alpha=0.3, which="both")
    fig.tight_layout()
    fig.savefig("accuracy.png", dpi=110)
