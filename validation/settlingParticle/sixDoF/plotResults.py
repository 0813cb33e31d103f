#!/usr/bin/python3
"""Collect and plot the settling disk, stock OpenFOAM body-fitted vs fbmFoam.

One disk (R = 0.125, d = 0.25, rho_s = 1.5) released from rest at (1, 4) in
a 2 x 6 channel, rho_f = 1, nu = 0.1, g = 980 (cgs; reference.md
section 2). Reads every run in runs/ (made by ./Allrun):

    runs/bodyFitted-L<N>        pimpleFoam, morphing O-grid, sixDoF body,
                                mesh re-referenced every 30 % of the gap
    runs/bodyFittedSingle-L<N>  the same with one mesh motion throughout
    runs/fbmFoam-L<N>           fbmFoam, tutorials/fbmFoam/settlingParticle
                                with the DKT contact model
    runs/fbmFoamScaled-L<N>     the same, the contact model scaled with h
    runs/fbmFoamDamped-L<N>     scaled, and with a normal dashpot

and writes

    results.csv   one row per run (columns below)
    sixDoF.png    settling speed v(t), the gap to the bottom wall, and
                  Re_max against CPU time

Definitions: Re = rho_s |U_p| d / mu, mu = rho_f nu (as ../README.md).
Re_max is the maximum while the gap to the bottom wall (y - R) is at least
two diameters. Both methods peak 3-4 d above the wall; closer, the
body-fitted speed rises again (the morphing mesh is failing), and
../README.md's window (gap >= d) would take that artefact as the maximum.
Re_max_1d is the maximum with that window, for comparison. A run that ends
above 2 d has no Re_max (its peak may not have come). Cost is CPU time, the
solver's own ExecutionTime (summed over the body-fitted stages), not wall
time: the runs shared 2 cores with other work.

results.csv columns:
    method, level, cells
    Re_max, U_max           maximum while gap >= 2 d, and |U_p| there [cm/s]
    t_Re_max, gap_Re_max_d  when, and the gap there in diameters
    cpu_to_2d_s             CPU time from release to gap = 2 d (the cost
                            of Re_max)
    Re_max_1d               maximum while gap >= d (../README.md's window)
    gap_speedup_d           body-fitted: where the speed, after slowing
                            down towards the wall, rises again by more than
                            1 % before the record ends (gap in diameters at
                            the speed's minimum): the near-wall artefact
    t_end, gap_end_d        where the record ends
    end                     why it ends: endTime (fbmFoam, at rest on the
                            wall), timeStepCollapse (runTimeControl: dt
                            below 1e-6 s), cpuLimit (the body-fitted run's
                            CPU limit, bodyFitted/Allrun -maxCpu), error
                            (the solver stopped with an error)
    cpu_s                   CPU time of the whole run
    n_reReference           re-referenced meshes (body-fitted)
    t_mesh_failed, gap_mesh_failed_d
                            first written time checkMesh fails on
                            (body-fitted), and the gap there in diameters
    U_end                   |U_p| at the end of the record [cm/s]
"""
import csv
import glob
import math
import os
import re
import sys

R = 0.125
D = 2*R
NU = 0.1
RHO_S = 1.5
RHO_F = 1.0


def reynolds(speed):
    return RHO_S*speed*D/(RHO_F*NU)


def nCells(run):
    m = re.search(r"nCells:\s*(\d+)", open(os.path.join(run, "log.blockMesh")).read())
    return int(m.group(1))


def vec(text):
    return [float(v) for v in text.strip("() \n").split()]


def readBodyFitted(run):
    """Per step t, x, y, Ux, Uy, cumulative CPU over the stages."""
    t, x, y, ux, uy, cpu = [], [], [], [], [], []
    cpuBefore = 0.0
    for log in sorted(glob.glob(os.path.join(run, "log.pimpleFoam.*"))):
        time = None
        state = None
        last = 0.0
        for line in open(log):
            if line.startswith("Time = "):
                time = float(line.split()[2])
                state = None
            elif line.startswith("    Centre of mass:") and time is not None:
                state = vec(line.split(":", 1)[1])
            elif line.startswith("    Linear velocity:") and state is not None:
                u = vec(line.split(":", 1)[1])
                cur = (time, state[0], state[1], u[0], u[1])
            elif line.startswith("ExecutionTime") and state is not None:
                last = float(line.split()[2])
                # one record per time step: the state after the last
                # mesh update of the step
                if t and t[-1] == cur[0]:
                    for lst in (t, x, y, ux, uy, cpu):
                        lst.pop()
                for lst, v in zip((t, x, y, ux, uy), cur):
                    lst.append(v)
                cpu.append(cpuBefore + last)
        cpuBefore += last
    return t, x, y, ux, uy, cpu, cpuBefore


def meshFailure(run):
    """First written time checkMesh fails on, or None."""
    path = os.path.join(run, "log.checkMesh")
    if not os.path.exists(path):
        return None
    time = None
    for line in open(path):
        if line.startswith("Time = "):
            try:
                time = float(line.split()[2])
            except ValueError:
                time = None
        elif line.startswith("Failed") and time is not None:
            return time
    return None


def readFbm(run):
    """particle.dat and the CPU time of each step from log.fbmFoam."""
    t, x, y, ux, uy = [], [], [], [], []
    for line in open(os.path.join(run, "postProcessing/fbmBodies/0/particle.dat")):
        if line.startswith("#"):
            continue
        v = [float(s) for s in line.split()]
        t.append(v[0]); x.append(v[7]); y.append(v[8])
        ux.append(v[10]); uy.append(v[11])
    stepCpu = {}
    time = None
    for line in open(os.path.join(run, "log.fbmFoam")):
        if line.startswith("Time = "):
            time = line.split()[2]
        elif line.startswith("ExecutionTime") and time is not None:
            stepCpu[float(time)] = float(line.split()[2])
    times = sorted(stepCpu)
    cpu = []
    j = 0
    for ti in t:
        while j + 1 < len(times) and times[j + 1] <= ti*(1 + 1e-12):
            j += 1
        cpu.append(stepCpu[times[j]] if times else float("nan"))
    total = stepCpu[times[-1]] if times else float("nan")
    return t, x, y, ux, uy, cpu, total


WINDOW = 2       # Re_max while the gap is at least WINDOW diameters


def summarise(method, level, run, data):
    t, x, y, ux, uy, cpu, total = data
    speed = [math.hypot(a, b) for a, b in zip(ux, uy)]
    gap = [yi - R for yi in y]
    row = {
        "method": method,
        "level": level,
        "cells": nCells(run),
        "t_end": "%.4f" % t[-1],
        "gap_end_d": "%.3f" % (gap[-1]/D),
        "cpu_s": "%.1f" % total,
        "U_end": "%.3f" % speed[-1],
    }
    iWindowEnd = next((i for i in range(len(t)) if gap[i] < WINDOW*D), None)
    if iWindowEnd is not None:
        iMax = max(range(iWindowEnd), key=lambda i: speed[i])
        row.update({
            "Re_max": "%.2f" % reynolds(speed[iMax]),
            "U_max": "%.3f" % speed[iMax],
            "t_Re_max": "%.4f" % t[iMax],
            "gap_Re_max_d": "%.2f" % (gap[iMax]/D),
            "cpu_to_2d_s": "%.1f" % cpu[iWindowEnd],
        })
        iEnd1 = next((i for i in range(len(t)) if gap[i] < D), len(t))
        row["Re_max_1d"] = "%.2f" % reynolds(max(speed[:iEnd1]))
        # body-fitted: the speed's minimum after the peak, if the speed
        # rises again by more than 1 % before the end (fbmFoam's rebound
        # off the contact is not meant)
        if method.startswith("bodyFitted"):
            iMin = min(range(iMax, len(t)), key=lambda i: speed[i])
            if max(speed[iMin:]) > 1.01*speed[iMin]:
                row["gap_speedup_d"] = "%.2f" % (gap[iMin]/D)
    if method.startswith("bodyFitted"):
        status = open(os.path.join(run, "runStatus")).read().split()
        row["end"] = status[0] if status else "unknown"
        rr = os.path.join(run, "log.reReference")
        row["n_reReference"] = (sum(1 for _ in open(rr))
                                if os.path.exists(rr) else 0)
        tFail = meshFailure(run)
        if tFail is not None:
            i = min(range(len(t)), key=lambda k: abs(t[k] - tFail))
            row["t_mesh_failed"] = "%.4f" % tFail
            row["gap_mesh_failed_d"] = "%.3f" % (gap[i]/D)
    else:
        exitStatus = open(os.path.join(run, "exitStatus")).read().strip()
        row["end"] = "endTime" if exitStatus == "0" else "error"
        row["n_reReference"] = ""
    return row


columns = ["method", "level", "cells", "Re_max", "U_max", "t_Re_max",
           "gap_Re_max_d", "cpu_to_2d_s", "Re_max_1d", "t_end", "gap_end_d",
           "end", "cpu_s", "n_reReference", "t_mesh_failed",
           "gap_mesh_failed_d", "gap_speedup_d", "U_end"]

runs = []
for run in sorted(glob.glob("runs/*-L*")):
    m = re.match(r"runs/(bodyFitted|bodyFittedSingle|fbmFoam|fbmFoamScaled|"
                 r"fbmFoamDamped)"
                 r"-L(\d+)$", run)
    if m is None:
        continue
    method, level = m.group(1), int(m.group(2))
    try:
        data = (readBodyFitted(run) if method.startswith("bodyFitted")
                else readFbm(run))
        runs.append((method, level, data, summarise(method, level, run, data)))
    except (OSError, ValueError, IndexError) as err:
        print(f"{run}: skipped ({err})", file=sys.stderr)

order = {"bodyFitted": 0, "bodyFittedSingle": 1, "fbmFoam": 2,
         "fbmFoamScaled": 3, "fbmFoamDamped": 4}
runs.sort(key=lambda r: (order[r[0]], r[1]))

if runs:
    with open("results.csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=columns, restval="")
        w.writeheader()
        for r in runs:
            w.writerow(r[3])
    print(open("results.csv").read())
else:
    print("No runs in runs/: results.csv not rewritten", file=sys.stderr)
    sys.exit(0)

# ---------------------------------------------------------------------------
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

style = {
    ("bodyFitted", 1): dict(color="tab:blue", ls="-"),
    ("bodyFitted", 2): dict(color="navy", ls="-"),
    ("bodyFittedSingle", 1): dict(color="tab:cyan", ls=":"),
    ("bodyFittedSingle", 2): dict(color="teal", ls=":"),
    ("fbmFoam", 3): dict(color="tab:orange", ls="--"),
    ("fbmFoam", 4): dict(color="tab:red", ls="--"),
    ("fbmFoamScaled", 4): dict(color="darkred", ls="-."),
    ("fbmFoamDamped", 4): dict(color="purple", ls=(0, (1, 1))),
}
label = {
    "bodyFitted": "body-fitted, re-referenced",
    "bodyFittedSingle": "body-fitted, one mesh motion",
    "fbmFoam": "fbmFoam",
    "fbmFoamScaled": "fbmFoam, contact scaled with h",
    "fbmFoamDamped": "fbmFoam, contact scaled + dashpot",
}
endMark = {"endTime": "o", "timeStepCollapse": "x", "error": "X", "cpuLimit": "s",
           "maxStages": "P", "unknown": "?"}

fig, (ax1, ax2, ax3) = plt.subplots(1, 3, figsize=(16, 5.2))
for method, level, data, row in runs:
    t, x, y, ux, uy, cpu, total = data
    st = style.get((method, level), dict(color="k", ls="-"))
    lab = "%s L%d (%s cells)" % (label[method], level, format(row["cells"], ","))
    v = [-u for u in uy]
    ax1.plot(t, v, lw=1.3, label=lab, **st)
    ax1.plot(t[-1], v[-1], endMark.get(row["end"], "?"), color=st["color"],
             ms=8, mfc="none" if row["end"] == "endTime" else st["color"])
    gap = [max(yi - R, 1e-4)/D for yi in y]
    ax2.semilogy(t, gap, lw=1.3, **st)
    ax2.plot(t[-1], gap[-1], endMark.get(row["end"], "?"), color=st["color"],
             ms=8, mfc="none" if row["end"] == "endTime" else st["color"])
    if row.get("t_mesh_failed"):
        ax2.plot(float(row["t_mesh_failed"]), float(row["gap_mesh_failed_d"]),
                 "D", color=st["color"], ms=6, mfc="none")
    if row.get("Re_max") and method in ("bodyFitted", "fbmFoam"):
        ax3.plot(float(row["cpu_to_2d_s"]), float(row["Re_max"]), "o",
                 color=st["color"], ms=8, label=lab)
        ax3.annotate("L%d" % level, (float(row["cpu_to_2d_s"]),
                                     float(row["Re_max"])),
                     textcoords="offset points", xytext=(6, 4), fontsize=8)

ax1.set_xlabel("t [s]")
ax1.set_ylabel("settling speed -U_y [cm/s]")
ax1.set_title("v(t); end: o end time, x time-step collapse, s CPU limit, "
              "X error", fontsize=9)
ax1.grid(alpha=0.3)
ax1.set_ylim(-1.5, 12.5)
offScale = ["%s L%d %.1f" % (label[r[0]], r[1], float(r[3]["U_end"]))
            for r in runs if float(r[3]["U_end"]) > 12.5]
if offScale:
    ax1.text(0.02, 0.97, "off scale at the end [cm/s]:\n" + "\n".join(offScale),
             transform=ax1.transAxes, fontsize=7, va="top")
ax1.legend(fontsize=7, loc="lower center")
ax2.axhline(1, color="grey", lw=0.8, ls=":")
ax2.axhline(WINDOW, color="grey", lw=0.8, ls="--")
ax2.set_xlabel("t [s]")
ax2.set_ylabel("gap to the bottom wall (y - R) / d")
ax2.set_title("gap to the wall (dashed: 2 d; diamond: first written mesh "
              "failing checkMesh)", fontsize=9)
ax2.grid(alpha=0.3, which="both")
ax3.set_xscale("log")
ax3.set_xlabel("CPU time from release to gap = 2 d [s]")
ax3.set_ylabel("Re_max = rho_s |U_p| d / mu (gap >= 2 d)")
finest = [float(r[3]["Re_max"]) for r in runs
          if r[0] == "bodyFitted" and r[3].get("Re_max")]
if finest:
    ax3.axhline(finest[-1], color="grey", lw=0.8, ls=":")
ax3.set_title("Re_max against cost (the fbmFoam contact variants are the "
              "same run before the wall)", fontsize=8)
ax3.grid(alpha=0.3, which="both")
ax3.legend(fontsize=7)
fig.suptitle("Settling disk, nu = 0.1, rho_s = 1.5: stock OpenFOAM "
             "body-fitted (pimpleFoam + sixDoF, morphing mesh) vs fbmFoam",
             fontsize=11)
fig.tight_layout()
fig.savefig("sixDoF.png", dpi=110)
print("sixDoF.png written")
