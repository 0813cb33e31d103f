#!/usr/bin/python3
"""Analyse the Jeffery-orbit runs in runs/ (see Allrun).

The ellipse (a = 1, b = 0.5; runs L*) and the prolate spheroid (semi-axes
1, 0.5, 0.5, its axis in the flow-gradient plane; runs spheroid-*) turn with
the shear u = gammaDot y (gammaDot = 1); Jeffery's law for the angle theta
of the major axis (the spheroid's from its quaternion, 2 atan2(qz, qw),
unwrapped),
    omega_J(theta) = -gammaDot (a^2 sin^2 theta + b^2 cos^2 theta)/(a^2 + b^2),
gives the period T_J = 2 pi (a/b + b/a)/gammaDot = 15.708.

For each run: the times at which theta passes -pi/2, -3 pi/2 and -5 pi/2
(linear interpolation between steps); the period T (from -pi/2 to -5 pi/2,
one full turn after the start-up) and the half periods; the angular
velocity against theta after the first crossing: its rms difference from
omega_J(theta) relative to the rms of omega_J, and its smallest and largest
|omega| (exact: 0.2 and 0.8 gammaDot); CPU: the solver's last
ExecutionTime. A run that stopped (the explicit coupling) is a row with its
stop time and message. Writes results.csv, table.md and omega.png.
"""
import csv
import glob
import math
import os
import re

import numpy as np

a, b, gammaDot = 1.0, 0.5, 1.0
TJ = 2*math.pi*(a/b + b/a)/gammaDot


def omegaJ(theta):
    return -gammaDot*(a**2*np.sin(theta)**2 + b**2*np.cos(theta)**2)/(a**2 + b**2)


def crossings(t, theta, levels):
    out = []
    for lev in levels:
        i = np.nonzero((theta[:-1] > lev) & (theta[1:] <= lev))[0]
        if len(i) == 0:
            out.append(float("nan"))
            continue
        i = i[0]
        w = (theta[i] - lev)/(theta[i] - theta[i + 1])
        out.append(t[i] + w*(t[i + 1] - t[i]))
    return out


def cells(c):
    m = re.search(r"nCells:\s*(\d+)", open(os.path.join(c, "log.blockMesh")).read())
    return int(m.group(1))


def cpu(log):
    times = re.findall(r"^ExecutionTime = ([0-9.eE+-]+) s", log, re.M)
    return float(times[-1]) if times else float("nan")


def bodiesShare(log):
    """The bodies' share of the step [%] from fbmFoam's last cost split"""
    m = re.findall(r"^fbm: wall time per step .*?bodies \S+ s \(([0-9.]+) %\)", log, re.M)
    return float(m[-1]) if m else ""


def param(c, key):
    m = re.search(r"^%s\s+(\S+);" % key,
                  open(os.path.join(c, "system/caseParameters")).read(), re.M)
    return m.group(1)


order = ["L1", "L2", "L3", "L1-H16", "L1-Re0.2", "L1-Re0.05", "L1-explicit", "L1-nu100",
         "spheroid-L1", "spheroid-L1-H8"]
runs = sorted((os.path.basename(p) for p in glob.glob("runs/*")),
              key=lambda r: order.index(r) if r in order else len(order))
rows, curves = [], {}
for run in runs:
    c = os.path.join("runs", run)
    log = open(os.path.join(c, "log.fbmFoam")).read()
    spheroid = run.startswith("spheroid")
    d = np.loadtxt(os.path.join(c, "postProcessing/fbmBodies/0/%s.dat"
                                % ("spheroid" if spheroid else "ellipse")),
                   comments="#", ndmin=2)
    t, w = d[:, 0], d[:, 15]
    if spheroid:
        # The axis turns about z only: the rotation angle of the quaternion
        theta = np.unwrap(2*np.arctan2(d[:, 19], d[:, 16]))
    else:
        theta = d[:, 16]
    level, height = int(param(c, "level")), float(param(c, "height"))
    nu = float(param(c, "nu"))
    row = {
        "run": run, "body": "spheroid" if spheroid else "ellipse", "level": level, "b_h": 4*2**(level - 1), "height": height,
        "Re": gammaDot*a**2/nu, "coupling": param(c, "couplingModel"),
        "cells": cells(c), "steps": len(t), "cpu_s": cpu(log),
        "bodies_pct": bodiesShare(log),
        # the viscous number nu dt/h^2 of the last step (h = b/(b/h))
        "visc_number": nu*(t[-1] - t[-2])/(b/(4*2**(level - 1)))**2,
        "t_end": t[-1], "T": "", "T_err_pct": "", "half1": "", "half2": "",
        "omega_rms_err_pct": "", "omega_min": "", "omega_max": "",
        "stopped": "",
    }
    if "FOAM FATAL" in log:
        m = re.search(r"^Body \S+ at time (\S+) (runs away)", log, re.M)
        row["stopped"] = ("stopped at t = %.3g: %s" % (float(m.group(1)), m.group(2))
                          if m else "stopped (fatal error, see its log)")
    t1, t3, t5 = crossings(t, theta, [-math.pi/2, -3*math.pi/2, -5*math.pi/2])
    if not math.isnan(t5):
        row["T"] = t5 - t1
        row["T_err_pct"] = 100*(t5 - t1 - TJ)/TJ
        row["half1"], row["half2"] = t3 - t1, t5 - t3
        sel = t >= t1
        wJ = omegaJ(theta[sel])
        row["omega_rms_err_pct"] = 100*math.sqrt(np.mean((w[sel] - wJ)**2)/np.mean(wJ**2))
        row["omega_min"], row["omega_max"] = np.min(-w[sel]), np.max(-w[sel])
        curves[run] = (np.mod(-theta[sel], math.pi), -w[sel])
    rows.append(row)

# The period's dependence on the Reynolds number at level 1 in the same
# box: the quadratic through Re = 0.05, 0.1, 0.2 (Lagrange), at Re = 0
byRun = {r["run"]: r for r in rows}
derived = []
pts = [(byRun[n]["Re"], byRun[n]["T_err_pct"]) for n in ("L1-Re0.05", "L1", "L1-Re0.2")
       if n in byRun and byRun[n]["T"] != ""]
if len(pts) == 3:
    e0 = 0.0
    for i, (xi, yi) in enumerate(pts):
        li = 1.0
        for j, (xj, _) in enumerate(pts):
            if j != i:
                li *= (0 - xj)/(xi - xj)
        e0 += yi*li
    derived.append(("L1_T_err_pct_Re0", e0))
with open("derived.csv", "w") as f:
    f.write("quantity,value\n")
    for q, v in derived:
        f.write("%s,%.6g\n" % (q, v))

fields = list(rows[0].keys()) if rows else []
with open("results.csv", "w", newline="") as f:
    wr = csv.DictWriter(f, fields)
    wr.writeheader()
    for r in rows:
        wr.writerow({k: ("%.6g" % v if isinstance(v, float) else v) for k, v in r.items()})


def fmt(v, spec):
    return "" if v == "" else format(v, spec)


with open("table.md", "w") as f:
    f.write("Jeffery period T_J = 2 pi (a/b + b/a)/gammaDot = %.4f; exact |omega| "
            "from %.2f to %.2f gammaDot\n\n" % (TJ, b**2/(a**2 + b**2), a**2/(a**2 + b**2)))
    f.write("| run | b/h | box | Re | coupling | cells | T | T error | half periods "
            "| omega rms error | min..max abs(omega) | CPU s | bodies' share | note |\n")
    f.write("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n")
    for r in rows:
        f.write("| %s | %d | %g | %g | %s | %d | %s | %s | %s | %s | %s | %.0f | %s | %s |\n" % (
            r["run"], r["b_h"], r["height"], r["Re"], r["coupling"], r["cells"],
            fmt(r["T"], ".4f"),
            "" if r["T"] == "" else "%+.2f %%" % r["T_err_pct"],
            "" if r["T"] == "" else "%.4f, %.4f" % (r["half1"], r["half2"]),
            "" if r["T"] == "" else "%.2f %%" % r["omega_rms_err_pct"],
            "" if r["T"] == "" else "%.4f..%.4f" % (r["omega_min"], r["omega_max"]),
            r["cpu_s"], "" if r["bodies_pct"] == "" else "%.0f %%" % r["bodies_pct"],
            r["stopped"]))

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (ax, ax2) = plt.subplots(2, 1, figsize=(6.4, 6.4), sharex=True,
                                  gridspec_kw={"height_ratios": [3, 2]})
    th = np.linspace(0, math.pi, 400)
    ax.plot(np.degrees(th), -omegaJ(-th), "k-", lw=2.5, alpha=0.4,
            label="Jeffery (Stokes, unbounded)")
    for run, (x, y) in curves.items():
        o = np.argsort(x)
        ax.plot(np.degrees(x[o]), y[o], lw=1, label=run)
        ax2.plot(np.degrees(x[o]), 100*(y[o]/-omegaJ(-x[o]) - 1), lw=1, label=run)
    ax.set_ylabel("|omega| / gammaDot")
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    ax2.axhline(0, color="k", lw=0.8)
    ax2.set_xlabel("angle of the major axis below the flow direction [deg]")
    ax2.set_ylabel("|omega| / Jeffery's - 1 [%]")
    ax2.set_xlim(0, 180)
    ax2.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig("omega.png", dpi=110)
except ImportError:
    print("matplotlib missing: omega.png not drawn")
with open("table.md", "a") as f:
    for q, v in derived:
        f.write("\nThe level-1 period error extrapolated to Re = 0 (the quadratic "
                "through Re = 0.05, 0.1, 0.2): %+.2f %%\n" % v)
print(open("table.md").read())
