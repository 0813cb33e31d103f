#!/usr/bin/python3
"""Collect and plot the settling disk, stock OpenFOAM body-fitted vs fbmFoam.

One disk (R = 0.125, d = 0.25, rho_s = 1.5) released from rest at (1, 4) in
a 2 x 6 channel, rho_f = 1, nu = 0.1, g = 980 (cgs; reference.md
section 2). Reads every run in runs/ (made by ./Allrun):

    runs/bodyFitted-L<N>        pimpleFoam, morphing O-grid, sixDoF body,
                                mesh re-referenced every 30 % of the gap
    runs/bodyFittedSingle-L<N>  the same with one mesh motion throughout
    runs/bodyFittedRerun-L<N>   bodyFitted again, to time it beside the
                                free-fall fbmFoam runs
    runs/fbmFoam-L<N>           fbmFoam, tutorials/fbmFoam/settlingParticle
                                with the DKT contact model
    runs/fbmFoamScaled-L<N>     the same, the contact model scaled with h
    runs/fbmFoamDamped-L<N>     scaled, and with a normal dashpot
    runs/fbmExplicit-L<N>       fbmFoam, the tutorial until 2026-12-05
                                (explicit coupling, addedMassCoeff 1, one
                                outer corrector, extrapolatePredictor, the
                                Euler time scheme), no contact model, to
                                t = 0.47 (free fall only)
    runs/fbmBackward-L<N>       the same with the backward time scheme:
                                the tutorial as it is
    runs/fbmSemiImplicit-L<N>   fbmExplicit with coupling semiImplicit
    runs/fbmSemiImplicitBackward-L<N>
                                the same with the backward time scheme
    runs/fbmSemiImplicitBackwardSolved-L<N>
                                the same with semiImplicitCoeffs/impulse
                                solved (./Allrun -solved)
    runs/fbmSemiImplicitBackwardNewton-L<N>
                                the same with semiImplicitCoeffs/
                                pressureSolve newton (./Allrun -newton)
    runs/fbmOuter3-L<N>         the same with three outer correctors, no
                                extrapolatePredictor, no minIter (the
                                settings of the fbmFoam* runs above)
    runs/<method>CoOnly-L<N>    bodyFitted, fbmExplicit, fbmSemiImplicit
                                with the step set by maxCo 0.5 alone
                                (maxDeltaT 1 instead of 1e-3: ./Allrun
                                -courantOnly)
    runs/<method>Graded[CoOnly]-L<N>
                                fbmExplicit, fbmSemiImplicit on the mesh
                                graded across the channel to 2 h at the
                                side walls (./Allrun -graded, gradeMesh.py)
    runs/gradingSweep-<RATIO>   the tutorial at level 3, step by maxCo
                                alone, graded to RATIO h at the side walls
                                (./Allrun -gradingSweep): gradingSweep.csv

and writes

    results.csv   one row per run (columns below); a row of the existing
                  results.csv whose run is not in runs/ is kept as it is
                  (runs/ is scratch: the rows of earlier runs stay)
    goal.csv      per free-fall fbmFoam row (fbmOuter3, fbmExplicit,
                  fbmBackward, fbmSemiImplicit): its error against the finest
                  body-fitted run, the body-fitted CPU time at the same
                  error (along the body-fitted levels timed with them,
                  below) and the ratio of the two (the issue's goal: at
                  most 2); the CoOnly rows against bodyFittedCoOnly
    timing.csv    the CPU times of runs made more than once: each run
                  <method>-L<N> (tag "first") and its repeats
                  runs/<method>-L<N>-<tag> (./Allrun -tag), which go only
                  here
    sixDoF.png    settling speed v(t) and the gap to the bottom wall of the
                  runs in runs/, and the error of Re_max against the finest
                  body-fitted run's against CPU time (every row)

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
    end                     why it ends: endTime (fbmFoam: at rest on the
                            wall, or t = 0.47 for the free-fall runs),
                            timeStepCollapse (runTimeControl: dt
                            below 1e-6 s), cpuLimit (the body-fitted run's
                            CPU limit, bodyFitted/Allrun -maxCpu), error
                            (the solver stopped with an error)
    cpu_s                   CPU time of the whole run
    n_reReference           re-referenced meshes (body-fitted)
    t_mesh_failed, gap_mesh_failed_d
                            first written time checkMesh fails on
                            (body-fitted), and the gap there in diameters
    U_end                   |U_p| at the end of the record [cm/s]
    commit                  the repository's commit when the run was made
                            (runs/.../gitCommit; the scripts may have had
                            changes not yet committed); empty for the rows
                            of the first session (scripts of b84f189)
"""
import csv
import glob
import math
import os
import re
from re import match as reMatch
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
    commit = os.path.join(run, "gitCommit")
    if os.path.exists(commit):
        row["commit"] = (open(commit).read().split() or [""])[0]
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
           "gap_mesh_failed_d", "gap_speedup_d", "U_end", "commit"]

order = {"bodyFitted": 0, "bodyFittedSingle": 1, "bodyFittedRerun": 1.5,
         "bodyFittedCoOnly": 1.7,
         "fbmFoam": 2,
         "fbmFoamScaled": 3, "fbmFoamDamped": 4, "fbmOuter3": 5,
         "fbmExplicit": 6, "fbmSemiImplicit": 7,
         "fbmExplicitCoOnly": 8, "fbmSemiImplicitCoOnly": 9,
         "fbmExplicitGraded": 10, "fbmExplicitGradedCoOnly": 11,
         "fbmSemiImplicitGraded": 12, "fbmSemiImplicitGradedCoOnly": 13,
         "fbmBackward": 14, "fbmBackwardCoOnly": 15,
         "fbmBackwardGraded": 16, "fbmBackwardGradedCoOnly": 17,
         "fbmSemiImplicitBackward": 18,
         "fbmSemiImplicitBackwardCoOnly": 19,
         "fbmSemiImplicitBackwardGraded": 20,
         "fbmSemiImplicitBackwardGradedCoOnly": 21,
         "fbmSemiImplicitBackwardSolved": 21.5,
         "fbmSemiImplicitBackwardNewton": 21.7}
# Allrun -viscousRatio: the tutorial with maxViscousRatio set (VR<ratio>,
# '.' as 'p'), after the others in ascending ratio
for _run in glob.glob("runs/fbmSemiImplicitBackwardVR*-L*") + \
        ([r["method"] for r in csv.DictReader(open("results.csv"))]
         if os.path.exists("results.csv") else []):
    _m = re.search(r"(fbmSemiImplicitBackwardVR(\d+(?:p\d+)?))", _run)
    if _m:
        order[_m.group(1)] = 22 + float(_m.group(2).replace("p", "."))/100

runs = []
repeats = []
for run in sorted(glob.glob("runs/*-L*")):
    m = re.match(r"runs/(%s)-L(-?\d+)(?:-(\w+))?$" % "|".join(order), run)
    if m is None:
        continue
    method, level, tag = m.group(1), int(m.group(2)), m.group(3)
    try:
        data = (readBodyFitted(run) if method.startswith("bodyFitted")
                else readFbm(run))
        row = summarise(method, level, run, data)
    except (OSError, ValueError, IndexError) as err:
        print(f"{run}: skipped ({err})", file=sys.stderr)
        continue
    if tag:
        repeats.append((method, level, tag, row))
    else:
        runs.append((method, level, data, row))

runs.sort(key=lambda r: (order[r[0]], r[1]))

# Every row: the runs in runs/, and the rows of the existing results.csv
# whose run is not there (kept as they are)
rows = {(r[0], r[1]): r[3] for r in runs}
kept = []
keptKeys = set()
if os.path.exists("results.csv"):
    for old in csv.DictReader(open("results.csv")):
        key = (old["method"], int(old["level"]))
        if key not in rows and old["method"] in order:
            rows[key] = {c: old.get(c, "") for c in columns}
            kept.append("%s-L%d" % key)
            keptKeys.add(key)
if not runs:
    print("No runs in runs/: results.csv not rewritten", file=sys.stderr)
    sys.exit(0)
if kept:
    print("Kept from results.csv (not in runs/): " + " ".join(kept))
rows = [rows[k] for k in sorted(rows, key=lambda k: (order[k[0]], k[1]))]
with open("results.csv", "w", newline="") as f:
    w = csv.DictWriter(f, fieldnames=columns, restval="")
    w.writeheader()
    for r in rows:
        w.writerow(r)
print(open("results.csv").read())

# Repeated runs: the first run and its repeats
timingColumns = ["method", "level", "tag", "Re_max", "cpu_to_2d_s", "cpu_s",
                 "commit"]
# The repeats of the existing timing.csv whose run is not in runs/ stay
# (as results.csv's rows do)
if os.path.exists("timing.csv"):
    present = {(m, l, t) for m, l, t, _ in repeats}
    for old in csv.DictReader(open("timing.csv")):
        key = (old["method"], int(old["level"]), old["tag"])
        if old["tag"] != "first" and key not in present \
                and old["method"] in order:
            repeats.append(key + ({c: old.get(c, "") for c in timingColumns},))
if repeats:
    with open("timing.csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=timingColumns, restval="",
                           extrasaction="ignore")
        w.writeheader()
        for key in sorted({(m, l) for m, l, _, _ in repeats},
                          key=lambda k: (order[k[0]], k[1])):
            first = [r for r in rows
                     if (r["method"], int(r["level"])) == key]
            for r in first:
                w.writerow(dict(r, tag="first"))
            for m, l, tag, r in sorted(repeats, key=lambda x: x[2]):
                if (m, l) == key:
                    w.writerow(dict(r, tag=tag))
    print(open("timing.csv").read())

# The goal: fbmFoam's CPU time to gap 2 d at most twice the body-fitted
# solver's at the same error of Re_max. The errors are against the finest
# body-fitted level (Re_ref, bodyFitted). The CPU times change between
# sessions on the shared machine (body-fitted L1: bodyFitted and
# bodyFittedRerun), so the body-fitted CPU is taken from the runs timed with
# the free-fall fbmFoam runs: per level, bodyFittedRerun where there is
# one, else bodyFitted. The body-fitted CPU at an error e is interpolated
# linearly in log(CPU) against log(error) between the two body-fitted
# levels (error > 0) that bracket e, or extrapolated along the nearest two
# when e is above them (bf_how says which). An error below the smallest
# body-fitted one (L1's, 0.12 %) is not rated: it is of the size of the
# reference's own error.
goalColumns = ["method", "level", "Re_max", "err_pct", "cpu_to_2d_s",
               "bf_cpu_s", "bf_how", "ratio", "goal_met"]


def bodyFittedLine(coOnly=False):
    """(level, Re_max, CPU to 2 d) of the body-fitted levels, the rerun's
    CPU where there is one; coOnly: the bodyFittedCoOnly levels"""
    pts = {}
    for method in (("bodyFittedCoOnly",) if coOnly
                   else ("bodyFitted", "bodyFittedRerun")):
        for r in rows:
            if r["method"] == method and r["Re_max"]:
                pts[int(r["level"])] = (float(r["Re_max"]),
                                        float(r["cpu_to_2d_s"]))
    return sorted((lvl, re, c) for lvl, (re, c) in pts.items())


bfRows = sorted((int(r["level"]), float(r["Re_max"]), float(r["cpu_to_2d_s"]))
                for r in rows if r["method"] == "bodyFitted" and r["Re_max"])
goal = []


def errorLine(coOnly=False):
    """(error %, CPU to 2 d, level) of the body-fitted levels with an
    error"""
    return sorted((100*abs(re/reRef - 1), c, lvl)
                  for lvl, re, c in bodyFittedLine(coOnly)
                  if abs(re/reRef - 1) > 0)


if bfRows:
    reRef = bfRows[-1][1]
    bfPts = errorLine()
    bfPtsCo = errorLine(coOnly=True)
    for r in rows:
        if not r["method"].startswith(("fbmOuter3", "fbmExplicit",
                                       "fbmSemiImplicit", "fbmBackward")) \
                or not r["Re_max"]:
            continue
        pts = bfPtsCo if r["method"].endswith("CoOnly") else bfPts
        e = 100*abs(float(r["Re_max"])/reRef - 1)
        cpu = float(r["cpu_to_2d_s"])
        g = {"method": r["method"], "level": r["level"],
             "Re_max": r["Re_max"], "err_pct": "%.2f" % e,
             "cpu_to_2d_s": r["cpu_to_2d_s"]}
        if len(pts) >= 2 and 0 < e < pts[0][0]:
            # below the finest body-fitted error but the reference's: the
            # reference's own error (about L1's) cannot rate it
            g.update({"bf_how": "below L%d's error" % pts[0][2],
                      "goal_met": "not rated"})
        elif len(pts) >= 2 and e > 0:
            i = next((k for k in range(len(pts) - 1)
                      if pts[k][0] <= e <= pts[k + 1][0]), None)
            if i is not None:
                how = "interpolated L%d-L%d" % (pts[i][2], pts[i + 1][2])
            else:
                i = 0 if e < pts[0][0] else len(pts) - 2
                how = "extrapolated beyond L%d" % (
                    pts[0][2] if e < pts[0][0] else pts[-1][2])
            (e0, c0, _), (e1, c1, _) = pts[i], pts[i + 1]
            slope = math.log(c1/c0)/math.log(e1/e0)
            bfCpu = c0*(e/e0)**slope
            g.update({"bf_cpu_s": "%.3g" % bfCpu, "bf_how": how,
                      "ratio": "%.3g" % (cpu/bfCpu),
                      "goal_met": "yes" if cpu <= 2*bfCpu else "no"})
        goal.append(g)
    with open("goal.csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=goalColumns, restval="")
        w.writeheader()
        for g in goal:
            w.writerow(g)
    print(open("goal.csv").read())

# The grading sweep: Re_max against the side walls' cell size alone
sweep = []
for run in glob.glob("runs/gradingSweep-*"):
    try:
        ratio = float(run.split("gradingSweep-")[1])
        data = readFbm(run)
        row = summarise("gradingSweep", 3, run, data)
    except (OSError, ValueError, IndexError) as err:
        print(f"{run}: skipped ({err})", file=sys.stderr)
        continue
    mesh = open(os.path.join(run, "log.gradeMesh")).read().split(":")[1]
    nx = sum(int(n) for n in mesh.split("cells")[0].split("+"))
    sweep.append({"ratio": "%g" % ratio, "nx": nx, "cells": row["cells"],
                  "Re_max": row.get("Re_max", ""),
                  "err_pct": ("%.2f" % (100*(float(row["Re_max"])/reRef - 1))
                              if row.get("Re_max") and bfRows else ""),
                  "cpu_to_2d_s": row.get("cpu_to_2d_s", ""),
                  "commit": row.get("commit", "")})
if sweep:
    sweep.sort(key=lambda r: float(r["ratio"]))
    with open("gradingSweep.csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(sweep[0]))
        w.writeheader()
        for r in sweep:
            w.writerow(r)
    print(open("gradingSweep.csv").read())

# ---------------------------------------------------------------------------
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

style = {
    ("bodyFitted", -1): dict(color="grey", ls="-"),
    ("bodyFitted", 0): dict(color="black", ls="-"),
    ("bodyFitted", 1): dict(color="tab:blue", ls="-"),
    ("bodyFitted", 2): dict(color="navy", ls="-"),
    ("bodyFittedSingle", 1): dict(color="tab:cyan", ls=":"),
    ("bodyFittedSingle", 2): dict(color="teal", ls=":"),
    ("bodyFittedRerun", 1): dict(color="tab:blue", ls="-"),
    ("bodyFittedRerun", 2): dict(color="navy", ls="-"),
    ("fbmFoam", 3): dict(color="tab:orange", ls="--"),
    ("fbmFoam", 4): dict(color="tab:red", ls="--"),
    ("fbmFoamScaled", 4): dict(color="darkred", ls="-."),
    ("fbmFoamDamped", 4): dict(color="purple", ls=(0, (1, 1))),
}
label = {
    "bodyFitted": "body-fitted, re-referenced",
    "bodyFittedSingle": "body-fitted, one mesh motion",
    "bodyFittedRerun": "body-fitted, re-referenced, rerun",
    "fbmFoam": "fbmFoam",
    "fbmFoamScaled": "fbmFoam, contact scaled with h",
    "fbmFoamDamped": "fbmFoam, contact scaled + dashpot",
    "fbmOuter3": "fbmFoam, 3 outer correctors",
    "fbmExplicit": "fbmFoam, explicit, extrapolated, Euler",
    "fbmBackward": "fbmFoam, explicit, extrapolated, backward",
    "fbmBackwardCoOnly": "fbmFoam, explicit backward, step by maxCo alone",
    "fbmBackwardGraded": "fbmFoam, explicit backward, graded mesh",
    "fbmBackwardGradedCoOnly": "fbmFoam, explicit backward, graded mesh, step by "
                               "maxCo alone",
    "fbmSemiImplicit": "fbmFoam, semiImplicit",
    "fbmSemiImplicitBackward": "fbmFoam, tutorial (semiImplicit, backward)",
    "fbmSemiImplicitBackwardCoOnly": "fbmFoam, semiImplicit, backward, step "
                                     "by maxCo alone",
    "fbmSemiImplicitBackwardGraded": "fbmFoam, semiImplicit, backward, "
                                     "graded mesh",
    "fbmSemiImplicitBackwardGradedCoOnly": "fbmFoam, semiImplicit, backward, "
                                           "graded mesh, step by maxCo alone",
    "fbmSemiImplicitBackwardSolved": "fbmFoam, tutorial with impulse solved",
    "fbmSemiImplicitBackwardNewton": "fbmFoam, tutorial with pressureSolve "
                                     "newton",
    "bodyFittedCoOnly": "body-fitted, step by maxCo alone",
    "fbmExplicitCoOnly": "fbmFoam, explicit Euler, step by maxCo alone",
    "fbmSemiImplicitCoOnly": "fbmFoam, semiImplicit, step by maxCo alone",
    "fbmExplicitGraded": "fbmFoam, explicit Euler, graded mesh",
    "fbmExplicitGradedCoOnly": "fbmFoam, explicit Euler, graded mesh, step by "
                               "maxCo alone",
    "fbmSemiImplicitGraded": "fbmFoam, semiImplicit, graded mesh",
    "fbmSemiImplicitGradedCoOnly": "fbmFoam, semiImplicit, graded mesh, "
                                   "step by maxCo alone",
}
# Allrun -viscousRatio
for _m in order:
    _v = re.match(r"fbmSemiImplicitBackwardVR(.*)$", _m)
    if _v:
        label[_m] = ("fbmFoam, tutorial, maxViscousRatio %s"
                     % _v.group(1).replace("p", "."))
# The free-fall runs: one colour per method, the level in the line style
methodColour = {"fbmOuter3": "tab:orange", "fbmExplicit": "tab:green",
                "fbmSemiImplicit": "tab:purple",
                "fbmExplicitCoOnly": "olive",
                "fbmSemiImplicitCoOnly": "tab:pink",
                "fbmExplicitGraded": "tab:cyan",
                "fbmExplicitGradedCoOnly": "darkcyan",
                "fbmSemiImplicitGraded": "tab:brown",
                "fbmSemiImplicitGradedCoOnly": "sienna",
                "fbmBackward": "black", "fbmBackwardCoOnly": "dimgray",
                "fbmBackwardGraded": "darkgoldenrod",
                "fbmBackwardGradedCoOnly": "goldenrod",
                "fbmSemiImplicitBackward": "tab:red",
                "fbmSemiImplicitBackwardCoOnly": "salmon",
                "fbmSemiImplicitBackwardGraded": "darkred",
                "fbmSemiImplicitBackwardGradedCoOnly": "indianred",
                "fbmSemiImplicitBackwardSolved": "tab:blue",
                "fbmSemiImplicitBackwardNewton": "tab:green"}
levelStyle = {3: "--", 4: "-", 5: "-."}
for m, c in methodColour.items():
    for lvl, ls in levelStyle.items():
        style[(m, lvl)] = dict(color=c, ls=ls)
endMark = {"endTime": "o", "timeStepCollapse": "x", "error": "X", "cpuLimit": "s",
           "maxStages": "P", "unknown": "?"}

fig, (ax1, ax2, ax3) = plt.subplots(1, 3, figsize=(16, 9))
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
ax1.legend(fontsize=6, loc="upper center", bbox_to_anchor=(0.5, -0.1),
           ncol=2)
ax2.axhline(1, color="grey", lw=0.8, ls=":")
ax2.axhline(WINDOW, color="grey", lw=0.8, ls="--")
ax2.set_xlabel("t [s]")
ax2.set_ylabel("gap to the bottom wall (y - R) / d")
ax2.set_title("gap to the wall (dashed: 2 d; diamond: first written mesh "
              "failing checkMesh)", fontsize=9)
ax2.grid(alpha=0.3, which="both")

# Accuracy against cost, every row: |Re_max - Re_ref| / Re_ref with Re_ref
# the finest body-fitted run's Re_max, against the CPU time to gap 2 d; one
# line per method over its levels. The reference run itself (error 0) is
# drawn on the lower edge. The fbmFoam contact variants are the same run
# as fbmFoam before the wall: left out. Runs of the earlier session (the
# rows kept from results.csv: body-fitted L1 and L2, fbmFoam) open symbols.
accuracy = [("bodyFitted", "body-fitted, re-referenced (L1: its rerun)",
             "tab:blue", "o"),
            ("fbmFoam", "fbmFoam, 3 outer correctors, earlier session "
             "(runs to the wall)", "tab:red", "s"),
            ("fbmOuter3", "fbmFoam, 3 outer correctors", "tab:orange", "s"),
            ("fbmExplicit", "fbmFoam, 1 corrector, extrapolated, "
             "explicit, Euler (the tutorial until 2026-12-05)", "tab:green",
             "D"),
            ("fbmBackward", "fbmFoam, explicit: the same with backward",
             "black", "P"),
            ("fbmBackwardCoOnly", "fbmFoam explicit backward, step by "
             "maxCo 0.5 alone", "dimgray", "P"),
            ("fbmBackwardGraded", "fbmFoam explicit backward, graded mesh",
             "darkgoldenrod", "P"),
            ("fbmBackwardGradedCoOnly", "fbmFoam explicit backward, graded "
             "mesh, step by maxCo alone", "goldenrod", "P"),
            ("fbmSemiImplicit", "fbmFoam, the same with coupling "
             "semiImplicit", "tab:purple", "^"),
            ("bodyFittedCoOnly", "body-fitted, step by maxCo 0.5 alone "
             "(maxDeltaT 1)", "navy", "o"),
            ("fbmExplicitCoOnly", "fbmFoam explicit, step by maxCo 0.5 "
             "alone", "olive", "D"),
            ("fbmSemiImplicitCoOnly", "fbmFoam semiImplicit, step by maxCo "
             "0.5 alone", "tab:pink", "^"),
            ("fbmExplicitGraded", "fbmFoam explicit, graded mesh",
             "tab:cyan", "D"),
            ("fbmExplicitGradedCoOnly", "fbmFoam explicit, graded mesh, "
             "step by maxCo alone", "darkcyan", "D"),
            ("fbmSemiImplicitGraded", "fbmFoam semiImplicit, graded mesh",
             "tab:brown", "^"),
            ("fbmSemiImplicitGradedCoOnly", "fbmFoam semiImplicit, graded "
             "mesh, step by maxCo alone", "sienna", "^"),
            ("fbmSemiImplicitBackward", "fbmFoam, tutorial since 2026-12-05: "
             "semiImplicit, backward", "tab:red", "v"),
            ("fbmSemiImplicitBackwardCoOnly", "fbmFoam semiImplicit "
             "backward, step by maxCo alone", "salmon", "v"),
            ("fbmSemiImplicitBackwardGraded", "fbmFoam semiImplicit "
             "backward, graded mesh", "darkred", "v"),
            ("fbmSemiImplicitBackwardGradedCoOnly", "fbmFoam semiImplicit "
             "backward, graded mesh, step by maxCo alone", "indianred",
             "v"),
            ("fbmSemiImplicitBackwardSolved", "fbmFoam, tutorial with "
             "semiImplicitCoeffs/impulse solved", "tab:blue", "v"),
            ("fbmSemiImplicitBackwardNewton", "fbmFoam, tutorial with "
             "semiImplicitCoeffs/pressureSolve newton", "tab:green", "P")]
floor = 0.02
if bfRows:
    for method, lab, colour, marker in accuracy:
        if method == "bodyFitted":
            # the rerun's CPU where there is one (as the goal), the
            # earlier run's beside it
            rerun = {int(r["level"]) for r in rows
                     if r["method"] == "bodyFittedRerun" and r["Re_max"]}
            pts = [(lvl, c, 100*abs(re/reRef - 1),
                    ("bodyFitted", lvl) in keptKeys and lvl not in rerun)
                   for lvl, re, c in bodyFittedLine()]
            for lvl, re, c in bfRows:
                if lvl in rerun:
                    ax3.loglog(c, 100*abs(re/reRef - 1), marker,
                               color=colour, ms=7, mfc="white")
                    ax3.annotate("L%d, earlier session" % lvl,
                                 (c, 100*abs(re/reRef - 1)),
                                 textcoords="offset points", xytext=(-25, -12),
                                 fontsize=7, color=colour)
        else:
            pts = sorted((int(r["level"]), float(r["cpu_to_2d_s"]),
                          100*abs(float(r["Re_max"])/reRef - 1),
                          (r["method"], int(r["level"])) in keptKeys)
                         for r in rows if r["method"] == method and r["Re_max"])
        if not pts:
            continue
        nonzero = [p for p in pts if p[2] > 0]
        ax3.loglog([p[1] for p in nonzero], [p[2] for p in nonzero], "-",
                   color=colour, lw=1.2)
        for lvl, c, e, old in nonzero:
            ax3.loglog(c, e, marker, color=colour, ms=7,
                       mfc="white" if old else colour)
            ax3.annotate("L%d" % lvl, (c, e), textcoords="offset points",
                         xytext=(5, 4), fontsize=7, color=colour)
        ax3.plot([], [], marker, color=colour, ls="-", label=lab)
        # The reference itself (error 0): on the lower edge, joined by a
        # dotted line
        for i, (lvl, c, e, old) in enumerate(pts):
            if e > 0:
                continue
            if i > 0:
                ax3.loglog([pts[i - 1][1], c], [pts[i - 1][2], floor], ":",
                           color=colour, lw=1)
            ax3.loglog(c, floor, "v", color=colour, ms=8, clip_on=False,
                       mfc="white" if old else colour)
            ax3.annotate("L%d: the reference\n(error 0)" % lvl, (c, floor),
                         textcoords="offset points", xytext=(6, 4),
                         fontsize=7, color=colour)
    # The goal: fbmFoam at most twice the body-fitted CPU at equal error,
    # along the body-fitted levels timed with the free-fall runs, and its
    # extrapolation to the larger errors of the fbmFoam runs
    if len(bfPts) >= 2:
        (e0, c0, _), (e1, c1, _) = bfPts[-2], bfPts[-1]
        slope = math.log(c1/c0)/math.log(e1/e0)
        ax3.loglog([2*p[1] for p in bfPts], [p[0] for p in bfPts], "--",
                   color="tab:blue", lw=1, alpha=0.7,
                   label="2 x body-fitted CPU (L1: its rerun): the goal, "
                         "fbmFoam left of it")
        eMax = max([float(g["err_pct"]) for g in goal] + [e1])
        if eMax > e1:
            ax3.loglog([2*c1, 2*c1*(eMax/e1)**slope], [e1, eMax], ":",
                       color="tab:blue", lw=1, alpha=0.7,
                       label="the same, extrapolated")
    if len(bfPtsCo) >= 2:
        ax3.loglog([2*p[1] for p in bfPtsCo], [p[0] for p in bfPtsCo], "--",
                   color="navy", lw=1, alpha=0.7,
                   label="2 x body-fitted CPU, step by maxCo alone: the "
                         "goal of the CoOnly rows")
    # The tutorial at level 5 with the viscous limit's ratio set
    # (Allrun -viscousRatio) beside its default (1.6): one line over the
    # ratio
    vr = []
    for r in rows:
        v = reMatch(r"fbmSemiImplicitBackward(?:VR(.*))?$", r["method"])
        if v and str(r["level"]) == "5" and r["Re_max"]:
            vr.append((float(r["cpu_to_2d_s"]),
                       100*abs(float(r["Re_max"])/reRef - 1),
                       (v.group(1) or "1.6").replace("p", ".")))
    if len(vr) > 1:
        vr.sort()
        ax3.loglog([p[0] for p in vr], [p[1] for p in vr], ":",
                   color="tab:red", lw=1.2,
                   label="fbmFoam, tutorial at L5, maxViscousRatio "
                         "(default 1.6) as marked")
        for c, e, ratio in vr:
            ax3.loglog(c, e, "v", color="tab:red", ms=7, mfc="white")
            ax3.annotate("L5, %s" % ratio, (c, e), textcoords="offset points",
                         xytext=(5, -10), fontsize=7, color="tab:red")
    ax3.set_ylim(floor, 30)
ax3.set_xlabel("CPU time from release to gap = 2 d [s]")
ax3.set_ylabel("|Re_max / Re_max(body-fitted L%d) - 1| [%%]"
               % (bfRows[-1][0] if bfRows else 0))
ax3.set_title("Accuracy against cost: error of Re_max (gap >= 2 d) vs the "
              "finest body-fitted run\n(shared 2-core machine; open "
              "symbols: earlier session, CPU times about 1.5 x lower)",
              fontsize=8)
ax3.grid(alpha=0.3, which="both")
ax3.legend(fontsize=6, loc="upper center", bbox_to_anchor=(0.5, -0.1))
fig.suptitle("Settling disk, nu = 0.1, rho_s = 1.5: stock OpenFOAM "
             "body-fitted (pimpleFoam + sixDoF, morphing mesh) vs fbmFoam",
             fontsize=11)
fig.tight_layout()
fig.savefig("sixDoF.png", dpi=110, bbox_inches="tight")
print("sixDoF.png written")
