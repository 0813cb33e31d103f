#!/usr/bin/python3
"""Analyse the oscillating-cylinder runs in runs/ (see Allrun).

For each run, over the second period (5 <= t <= 10): the in-line force per
unit length F(t) (the runs' depth is 0.1), its peak amplitude (max - min)/2
and the amplitude of its first harmonic (a least-squares Fourier series of
harmonics 1-9), the noise (the rms of F less that series, relative to the
first harmonic: the step-to-step jumps as the body crosses cells), the rms
of its difference from the finest body-fitted run (interpolated on the same
times) relative to that run's peak amplitude, and Morison's coefficients
fitted by least squares,
    F = -1/2 rho D Cd U|U| - rho pi D^2/4 Ci dU/dt,
with the cylinder's velocity U = -Umax cos(2 pi f t) (Umax = 1, f = 0.2,
D = 1, rho = 1). CPU: the solver's ExecutionTime at t = 10. Writes results.csv,
table.md, force.png and accuracy.png.

Runs of the committed results.csv that are not in runs/ keep their row
(marked `kept` in the column rerun; in table.md their name carries a *):
their errors were taken against the body-fitted run of that time, and
their CPU time is from another machine state.
"""
import glob
import math
import os
import re

import numpy as np

depth, D, f, Umax = 0.1, 1.0, 0.2, 1.0
t0, t1 = 5.0, 10.0


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
    # CPU time up to the end of the period analysed
    cpu, cur = float("nan"), 0.0
    for line in open(log):
        if line.startswith("Time = "):
            cur = float(line.split()[2])
        elif line.startswith("ExecutionTime = ") and cur <= t1 + 1e-9:
            cpu = float(line.split()[2])
    nCells = int(re.search(r"nCells:\s*(\d+)",
                           open(os.path.join(c, "log.blockMesh")).read()).group(1))
    return t, F/depth, cpu, nCells


def fourier(t, F, n):
    """Least-squares Fourier series of F over whole periods, harmonics
    1..n of f: (the fitted values, the first harmonic's amplitude)"""
    w = 2*math.pi*f
    cols = [np.ones_like(t)]
    for k in range(1, n + 1):
        cols += [np.cos(k*w*t), np.sin(k*w*t)]
    A = np.column_stack(cols)
    c, *_ = np.linalg.lstsq(A, F, rcond=None)
    return A @ c, math.hypot(c[1], c[2])


def morison(t, F):
    w = 2*math.pi*f
    U = -Umax*np.cos(w*t)
    dU = Umax*w*np.sin(w*t)
    A = np.column_stack((-0.5*D*U*np.abs(U), -math.pi*D**2/4*dU))
    (Cd, Ci), *_ = np.linalg.lstsq(A, F, rcond=None)
    return Cd, Ci


def method(run):
    """fbm (lagged momentum predictor), fbm-extrap (extrapolated
    predictor), fbm-dt2 (half the step), fbm-vf (extrapolated, forcing
    volumeFraction) or bodyFitted"""
    m = run.split("-")[0]
    for suffix in ("-dt2", "-extrap", "-vf"):
        if run.endswith(suffix):
            m += suffix
    return m


cols = ["run", "method", "level", "cells", "steps", "cpu_s", "amplitude",
        "amplitude1", "noise_pct", "Cd", "Ci", "ampError_pct",
        "amp1Error_pct", "rmsError_pct", "rerun"]
# The committed rows, for the runs that are not redone
old = {}
if os.path.exists("results.csv"):
    lines = open("results.csv").read().split("\n")
    head = lines[0].split(",")
    for line in lines[1:]:
        if line.strip():
            row = dict(zip(head, line.split(",")))
            for k in row:
                if k not in ("run", "method", "rerun"):
                    row[k] = float(row[k]) if row[k] else None
            row = {k: v for k, v in row.items() if v is not None}
            row["rerun"] = "kept"
            old[row["run"]] = row

runs = sorted(os.path.basename(p) for p in glob.glob("runs/*-L*")
              if glob.glob(p + "/postProcessing/*/0/*.dat"))
data = {r: load(r) for r in runs}
# Only the runs that reached the end of the period analysed
runs = [r for r in runs if len(data[r][0]) and data[r][0][-1] >= t1 - 1e-9]
refs = sorted(r for r in runs if r.startswith("bodyFitted"))
ref = refs[-1] if refs else None

rows = []
for r in runs:
    t, F, cpu, n = data[r]
    m = (t >= t0 - 1e-9) & (t <= t1 + 1e-9)
    amp = 0.5*(F[m].max() - F[m].min())
    Cd, Ci = morison(t[m], F[m])
    smooth, amp1 = fourier(t[m], F[m], 9)
    noise = 100*math.sqrt(np.mean((F[m] - smooth)**2))/amp1
    row = dict(run=r, method=method(r), level=int(r.split("-L")[1][0]),
               cells=n, steps=int((t <= t1 + 1e-9).sum()), cpu_s=cpu,
               amplitude=amp, amplitude1=amp1, noise_pct=noise, Cd=Cd, Ci=Ci,
               rerun="yes")
    if ref:
        tr, Fr, _, _ = data[ref]
        mr = (tr >= t0 - 1e-9) & (tr <= t1 + 1e-9)
        ampRef = 0.5*(Fr[mr].max() - Fr[mr].min())
        _, amp1Ref = fourier(tr[mr], Fr[mr], 9)
        Fi = np.interp(t[m], tr, Fr)
        row["ampError_pct"] = 100*(amp/ampRef - 1)
        row["amp1Error_pct"] = 100*(amp1/amp1Ref - 1)
        row["rmsError_pct"] = 100*math.sqrt(np.mean((F[m] - Fi)**2))/ampRef
    rows.append(row)
rows += [row for r, row in old.items() if r not in runs and r != "run"]
order = ["bodyFitted", "fbm", "fbm-dt2", "fbm-extrap", "fbm-vf"]
rows.sort(key=lambda row: (order.index(row["method"]) if row["method"] in order
                           else len(order), row["level"], row["run"]))

with open("results.csv", "w") as out:
    out.write(",".join(cols) + "\n")
    for row in rows:
        out.write(",".join(
            ("%.5g" % row[c]) if isinstance(row.get(c), float)
            else str(int(row[c])) if c in ("level", "cells", "steps")
            else str(row.get(c, ""))
            for c in cols) + "\n")

with open("table.md", "w") as out:
    out.write("In-line force per unit length over the second period "
              "(5 <= t <= 10); errors against %s; fbm: lagged momentum "
              "predictor, -extrap: extrapolated (extrapolatePredictor yes, "
              "minIter 10), both forcing linearProfile; -vf: extrapolated, forcing "
              "volumeFraction%s\n\n" % (ref, "; *: not rerun, the row of the "
              "earlier results.csv" if any(row["rerun"] == "kept" for row in rows)
              else ""))
    out.write("| run | cells | steps | CPU s | peak amplitude | first harmonic "
              "| noise | Cd | Ci | peak error | harmonic error | rms error |\n"
              "|---|---|---|---|---|---|---|---|---|---|---|---|\n")
    for row in rows:
        e = lambda k, fmt: (fmt % row[k]) if k in row else ""
        out.write("| %s | %d | %d | %.0f | %.4f | %.4f | %.2f %% | %.3f | %.3f "
                  "| %s | %s | %s |\n" % (
            row["run"] + ("*" if row["rerun"] == "kept" else ""), row["cells"], row["steps"], row["cpu_s"],
            row["amplitude"], row["amplitude1"], row["noise_pct"], row["Cd"],
            row["Ci"], e("ampError_pct", "%+.2f %%"),
            e("amp1Error_pct", "%+.2f %%"), e("rmsError_pct", "%.2f %%")))
print(open("table.md").read())

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import matplotlib.ticker

fig, ax = plt.subplots(figsize=(7, 4))
for r in runs:
    t, F, _, _ = data[r]
    m = t >= t0 - 1e-9
    ax.plot((t[m] - t0)/5, F[m], "-" if r.startswith("bodyFitted") else "--",
            label=r)
ax.set_xlabel("t/T - 1 (second period)")
ax.set_ylabel("in-line force F_x per unit length")
ax.legend()
ax.grid(alpha=0.3)
fig.tight_layout()
fig.savefig("force.png", dpi=110)

if ref:
    fig, axs = plt.subplots(1, 2, figsize=(10, 4))
    labels = {"fbm": "fbm, lagged predictor", "fbm-dt2": "fbm lagged, half step",
              "fbm-extrap": "fbm, extrapolated predictor",
              "fbm-vf": "fbm, extrapolated, volumeFraction",
              "bodyFitted": "bodyFitted"}
    for ax, key, name in ((axs[0], "amp1Error_pct", "|first-harmonic error| [%]"),
                          (axs[1], "rmsError_pct", "rms force error [% of peak amplitude]")):
        for m, mk in (("fbm", "o-"), ("fbm-extrap", "D-"), ("fbm-vf", "v-"),
                      ("fbm-dt2", "^"),
                      ("bodyFitted", "s-")):
            rr = [row for row in rows if row["method"] == m and row["run"] != ref
                  and key in row]
            if rr:
                ax.loglog([row["cpu_s"] for row in rr],
                          [max(abs(row[key]), 1e-3) for row in rr], mk,
                          label=labels[m] + " (levels %s)"
                          % ",".join(str(int(row["level"])) for row in rr))
        ax.set_xlabel("CPU s (to t = 10, two periods)")
        ax.set_ylabel(name)
        ax.yaxis.set_major_formatter(matplotlib.ticker.ScalarFormatter())
        ax.yaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
        ax.set_yticks([0.2, 0.5, 1, 2, 5, 10])
        ax.grid(alpha=0.3, which="both")
    axs[1].legend(fontsize=7, loc="lower left")
    fig.suptitle("Force errors against %s (the finest body-fitted run)" % ref,
                 fontsize=10)
    fig.tight_layout()
    fig.savefig("accuracy.png", dpi=110)
