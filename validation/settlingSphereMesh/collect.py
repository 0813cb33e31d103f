#!/usr/bin/python3
"""Collect the runs of ./Allrun into results.csv, history.csv and
convergence.csv.

results.csv, one row per run folder runs/<name>, from the body's record
(postProcessing/fbmBodies/0/<body>.dat: Time Fx Fy Fz Tx Ty Tz x y z Ux Uy
Uz wx wy wz; as ../projectionAccuracy/collect.py):
    body, coupling          sphere or disk2D; explicit or semiImplicit
    variant                 the run's name before -RH: explicit,
                            semiImplicit, explicitExtrap, semiImplicitExtrap,
                            explicitExtrapP, explicitExtrapBackward,
                            semiImplicitExtrapBackward (the backward time
                            scheme, the body stepped by Euler),
                            semiImplicitExtrapBackwardF (backward, the body
                            at the fluid's rate; the others Euler),
                            semiImplicitExtrapBackwardN (as F, with
                            pressureSolve newton)
    predictor               lagged, extrapolated flux (PIMPLE
                            extrapolatePredictor yes, extrapolatePressure
                            no, with minIter 10 for U) or extrapolated
                            (flux and pressure; with nCorrectors N when
                            not the tutorial's 2)
    R_h, h, cells           radius over cell size, cell size, cells
    steps, t_end            time steps and last time of the record
    max_speed, t_max        largest |U| and when
    speed_0.1, speed_0.15, speed_0.25  |U| at the last step at or before
                            t = 0.1, 0.15, 0.25 (empty when the record
                            ends before)
    mean_0.2_0.25           time-weighted mean of |U| over the steps in
                            (0.2, 0.25] (the sphere near its terminal
                            speed; filters a step-to-step oscillation)
    range_0.2_0.25_pct      (max - min)/mean of |U| over those steps in %
    fp_last_change, fp_ratio  the runs -n<K> (logged with DebugSwitches
                            { semiImplicit 1; }): the median over the steps
                            of the relative change of the pressure force
                            made by the last pressure corrector, and of its
                            ratio to the change made by the one before (the
                            contraction of the pressure step's fixed point)
    y_start, y_end          height of the centre at the first and last step
    bodyCo_max              largest body Courant number |U| dt / h
    cpu_s                   fbmFoam's last ExecutionTime
    cpu_ms_step             cpu_s per time step (ms)
    p_iters_step            GAMG iterations of p per time step (all the
                            step's pressure solves)
    U_sweeps_step           smoothSolver sweeps of Ux per time step
    warnings, warn_t, warn_ratio  coupling semiImplicit's warnings that a
                            step was above its viscous limit: how many,
                            the time of the first, the largest ratio it
                            gives (viscous/inertial diagonal; the limit is
                            maxViscousRatio)
    cpu_us_cellstep         cpu_s per cell and time step (microseconds)
    status                  exitStatus of the tutorial's Allrun (0: done)

history.csv: run, t, speed (|U| of the sphere at every step; the chart).

convergence.csv, one row per variant (column coupling) and quantity (speed at t = 0.1,
0.15, 0.25; t = 0.2-0.25: mean_0.2_0.25) over R/h = 3, 4, 6 (h = 1/60, 1/80, 1/120): the three values,
the change from R/h 4 to 6 in %, whether the differences have one sign
(monotone), and if so the observed order p from
    (u3 - u4)/(u4 - u6) = (h3^p - h4^p)/(h4^p - h6^p)
(the ratios 4/3 and 3/2 differ, so p is found by bisection in (0.05, 10))
and the Richardson-extrapolated value u6 + (u6 - u4)/((h4/h6)^p - 1);
empty when the levels do not converge monotonically.

Runs without runs/<name>/exitStatus (still running) are left out.

Usage: /usr/bin/python3 collect.py
"""
import csv
import glob
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "bin"))
import fbmOutput  # noqa: E402  (bin/fbmOutput.py: the shared reader)

HERE = os.path.dirname(os.path.abspath(__file__))

COLUMNS = ["run", "body", "coupling", "R_h", "h", "cells", "steps", "t_end",
           "max_speed", "t_max", "speed_0.1", "speed_0.15", "speed_0.25",
           "mean_0.2_0.25", "range_0.2_0.25_pct", "y_start", "y_end", "bodyCo_max", "cpu_s", "cpu_ms_step",
           "cpu_us_cellstep", "p_iters_step", "U_sweeps_step",
           "warnings", "warn_t", "warn_ratio", "status", "variant",
           "predictor", "fp_last_change", "fp_ratio"]
VARIANTS = ["explicit", "semiImplicit", "explicitExtrap", "semiImplicitExtrap",
            "explicitExtrapP", "explicitExtrapBackward",
            "semiImplicitExtrapBackward", "semiImplicitExtrapBackwardF",
            "semiImplicitExtrapBackwardN"]
# The pressure step's fixed point: semiImplicitExtrapBackwardF (and N, with
# pressureSolve newton) with more PISO
# correctors (-n<K>) or a smaller viscous limit (-r<X>); not in
# convergence.csv or the chart (not every mesh)
SWEEP = ["semiImplicitExtrapBackwardF-%s-RH%d" % (v, n)
         for v, n in (("n3", 3), ("n4", 3), ("n6", 3), ("r1.6", 3),
                      ("n4", 4), ("r1.6", 4))] \
    + ["semiImplicitExtrapBackwardN-n4-RH3",
       "semiImplicitExtrapBackwardN-n8-RH3",
       "semiImplicitExtrapBackwardN-r1.6-RH3"]
ORDER = ["%s-RH%d" % (v, n) for v in VARIANTS for n in (3, 4, 6)] \
    + ["disk2D-L4"] + SWEEP
TIMES = ["0.1", "0.15", "0.25"]


def lastMatch(path, pattern):
    value = ""
    try:
        with open(path, errors="replace") as f:
            for line in f:
                m = re.search(pattern, line)
                if m:
                    value = m.group(1)
    except OSError:
        pass
    return value


def iterations(path, field):
    """Sum of the iterations of the solves of field in a solver log"""
    total = 0
    with open(path, errors="replace") as f:
        for line in f:
            m = re.search(r"Solving for %s,.*No Iterations (\d+)" % field,
                          line)
            if m:
                total += int(m.group(1))
    return total


def fixedPoint(path):
    """(median change of the bodies' pressure force made by the last
    pressure corrector, median ratio of that change to the one before it)
    over the steps of a log written with DebugSwitches { semiImplicit 1; }
    (semiImplicit's reportForceChange); empty strings without it"""
    steps, step = [], []
    pattern = re.compile(r"^fbm: semiImplicit: pressure corrector (\d+) "
                         r"changed the bodies' pressure force by (\S+)")
    with open(path, errors="replace") as f:
        for line in f:
            if line.startswith("Time = "):
                if step:
                    steps.append(step)
                step = []
                continue
            m = pattern.match(line)
            if m:
                step.append(float(m.group(2)))
    if step:
        steps.append(step)
    steps = [c for c in steps if len(c) >= 2 and c[-2] > 0]
    if not steps:
        return "", ""
    last = sorted(c[-1] for c in steps)
    ratio = sorted(c[-1]/c[-2] for c in steps)
    return "%.3g" % last[len(last)//2], "%.3g" % ratio[len(ratio)//2]


def viscousWarnings(path):
    """(count, first time, largest ratio) of the viscous-limit warnings"""
    found = []
    with open(path, errors="replace") as f:
        for line in f:
            m = re.search(r"coupling semiImplicit at time ([0-9.e+-]+): "
                          r"the step .* is above its viscous.* is "
                          r"([0-9.e+-]+) times", line)
            if m:
                found.append((float(m.group(1)), float(m.group(2))))
    if not found:
        return 0, "", ""
    return (len(found), "%.4g" % found[0][0],
            "%.3g" % max(r for t, r in found))


def predictor(fvSolution):
    """lagged, extrapolated (flux and pressure) or extrapolated flux; the
    pressure as the run's log says (extrapolatePressure's default was yes
    before 2026-12-03 and is no since)"""
    text = open(fvSolution).read()
    if not re.search(r"^\s*extrapolatePredictor\s+(yes|on|true)\s*;",
                     text, re.M):
        return "lagged"
    log = os.path.join(os.path.dirname(os.path.dirname(fvSolution)),
                       "log.fbmFoam")
    logText = open(log).read() if os.path.exists(log) else ""
    if "extrapolatePredictor: flux and pressure" not in logText:
        if "extrapolatePredictor: flux of the first" not in logText:
            sys.exit("collect.py: %s does not say what the predictor"
                     " extrapolated" % log)
        return "extrapolated flux"
    m = re.search(r"^\s*nCorrectors\s+(\d+)\s*;", text, re.M)
    return "extrapolated" + (", nCorrectors %s" % m.group(1)
                             if m and m.group(1) != "2" else "")


def collectRun(run):
    name = os.path.basename(run)
    if name.startswith("disk2D"):
        body, bodyFile, radius = "disk2D", "particle", 0.125
        level = int(re.search(r"^level\s+(\d+);", open(os.path.join(
            run, "system/caseParameters")).read(), re.M).group(1))
        h = 2.0/(12*2**(level - 1))
    else:
        body, bodyFile, radius = "sphere", "sphere", 0.05
        nx = int(re.search(r"hex\s*\([^)]*\)\s*\((\d+)\s+\d+\s+\d+\)",
                           open(os.path.join(run, "system/blockMeshDict"))
                           .read()).group(1))
        h = 0.5/nx
    rows, t, speed = fbmOutput.bodyRecord(run, bodyFile)
    iMax = max(range(len(rows)), key=lambda i: speed[i])
    co = fbmOutput.largestBodyCourant(t, speed, h)

    def at(time):
        return fbmOutput.speedAt(t, speed, time)

    window = [(v, t[i] - t[i - 1]) for i, v in enumerate(speed)
              if i and 0.2 + 1e-9 < t[i] <= 0.25 + 1e-9]
    mean = sum(v*dt for v, dt in window)/sum(dt for v, dt in window) \
        if window and t[-1] >= 0.25 - 1e-9 else None

    props = open(os.path.join(run, "constant/fbmProperties")).read()
    m = re.search(r"^coupling\s+(\w+)\s*;", props, re.M)
    coupling = m.group(1) if m else "explicit"
    cells = lastMatch(os.path.join(run, "log.blockMesh"), r"nCells:\s*(\d+)")
    cpu = lastMatch(os.path.join(run, "log.fbmFoam"),
                    r"^ExecutionTime = ([0-9.e+-]+) s")
    try:
        status = open(os.path.join(run, "exitStatus")).read().strip()
    except OSError:
        status = "none"
    row = {"run": name, "body": body, "coupling": coupling,
           "R_h": "%g" % round(radius/h, 6), "h": "%.6g" % h,
           "cells": cells, "steps": len(rows), "t_end": "%.6g" % t[-1],
           "max_speed": "%.5g" % speed[iMax], "t_max": "%.4g" % t[iMax],
           "y_start": "%.5g" % rows[0][8], "y_end": "%.5g" % rows[-1][8],
           "bodyCo_max": "%.3g" % co,
           "cpu_s": "%.2f" % float(cpu) if cpu else "",
           "cpu_ms_step": "%.4g" % (1e3*float(cpu)/len(rows))
           if cpu else "",
           "cpu_us_cellstep": "%.4g" % (1e6*float(cpu)/len(rows)
                                        / float(cells))
           if cpu and cells else "",
           "p_iters_step": "%.3g" % (iterations(os.path.join(
               run, "log.fbmFoam"), "p")/len(rows)),
           "U_sweeps_step": "%.3g" % (iterations(os.path.join(
               run, "log.fbmFoam"), "Ux")/len(rows)),
           "status": status,
           "variant": name.split("-RH")[0] if body == "sphere" else "",
           "predictor": predictor(os.path.join(run, "system/fvSolution"))}
    row["warnings"], row["warn_t"], row["warn_ratio"] = viscousWarnings(
        os.path.join(run, "log.fbmFoam"))
    row["fp_last_change"], row["fp_ratio"] = fixedPoint(
        os.path.join(run, "log.fbmFoam"))
    for time in TIMES:
        row["speed_" + time] = at(float(time))
    row["mean_0.2_0.25"] = "%.5g" % mean if mean else ""
    row["range_0.2_0.25_pct"] = "%.3g" % (
        100*(max(v for v, dt in window) - min(v for v, dt in window))/mean) \
        if mean else ""
    history = [(name, "%.6g" % ti, "%.6g" % v) for ti, v in zip(t, speed)] \
        if body == "sphere" else []
    return row, history


def order(u, h):
    """Observed order from three values u on cells h (coarse to fine), or
    None when the differences change sign or no root lies in (0.05, 10)"""
    d1, d2 = u[0] - u[1], u[1] - u[2]
    if d1*d2 <= 0:
        return None
    ratio = d1/d2

    def f(p):
        return (h[0]**p - h[1]**p)/(h[1]**p - h[2]**p) - ratio

    lo, hi = 0.05, 10.0
    if f(lo)*f(hi) > 0:
        return None
    for _ in range(200):
        mid = 0.5*(lo + hi)
        if f(lo)*f(mid) <= 0:
            hi = mid
        else:
            lo = mid
    return 0.5*(lo + hi)


def convergence(results):
    out = []
    for coupling in VARIANTS:
        rows = [results.get("%s-RH%d" % (coupling, n)) for n in (3, 4, 6)]
        if None in rows:
            continue
        h = [float(r["h"]) for r in rows]
        for time in TIMES + ["0.2-0.25"]:
            key = "speed_" + time if time in TIMES else "mean_0.2_0.25"
            if "" in [r[key] for r in rows]:
                continue
            u = [float(r[key]) for r in rows]
            p = order(u, h)
            monotone = (u[0] - u[1])*(u[1] - u[2]) > 0
            row = {"coupling": coupling, "t": time, "speed_RH3": u[0],
                   "speed_RH4": u[1], "speed_RH6": u[2],
                   "change_3_4_pct": "%.3f" % (100*(u[1]/u[0] - 1)),
                   "change_4_6_pct": "%.3f" % (100*(u[2]/u[1] - 1)),
                   "monotone": "yes" if monotone else "no",
                   "order": "", "extrapolated": "", "RH6_vs_extrap_pct": ""}
            if p is not None:
                ext = u[2] + (u[2] - u[1])/((h[1]/h[2])**p - 1)
                row.update({"order": "%.3g" % p,
                            "extrapolated": "%.5g" % ext,
                            "RH6_vs_extrap_pct":
                            "%.3f" % (100*(u[2]/ext - 1))})
            out.append(row)
    return out


def main():
    runs = [r for r in glob.glob(os.path.join(HERE, "runs", "*"))
            if os.path.basename(r) in ORDER
            and os.path.isfile(os.path.join(r, "exitStatus"))]
    collected = {os.path.basename(r): collectRun(r) for r in runs}
    results = {n: c[0] for n, c in collected.items()}
    histories = {n: c[1] for n, c in collected.items()}
    # The rows of runs not in runs/ stay as they are in the csv files
    path = os.path.join(HERE, "results.csv")
    if os.path.isfile(path):
        for row in csv.DictReader(open(path)):
            if row["run"] in ORDER and row["run"] not in results:
                results[row["run"]] = row
    path = os.path.join(HERE, "history.csv")
    if os.path.isfile(path):
        for row in csv.DictReader(open(path)):
            if row["run"] in ORDER and row["run"] not in collected:
                histories.setdefault(row["run"], []).append(
                    (row["run"], row["t"], row["speed"]))
    with open(os.path.join(HERE, "results.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, COLUMNS, lineterminator="\n")
        w.writeheader()
        w.writerows(results[n] for n in ORDER if n in results)
    with open(os.path.join(HERE, "history.csv"), "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(["run", "t", "speed"])
        for n in ORDER:
            w.writerows(histories.get(n, []))
    conv = convergence(results)
    with open(os.path.join(HERE, "convergence.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, ["coupling", "t", "speed_RH3", "speed_RH4",
                               "speed_RH6", "change_3_4_pct",
                               "change_4_6_pct", "monotone", "order",
                               "extrapolated", "RH6_vs_extrap_pct"],
                           lineterminator="\n")
        w.writeheader()
        w.writerows(conv)
    for n in ORDER:
        if n in results:
            print(",".join(str(results[n].get(c, "")) for c in COLUMNS))
    for r in conv:
        print(r)
    print("Wrote results.csv, history.csv, convergence.csv")


if __name__ == "__main__":
    main()
