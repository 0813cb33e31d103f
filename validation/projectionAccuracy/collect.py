#!/usr/bin/python3
"""Collect the runs of ./Allrun into results.csv.

One row per run folder runs/<name>: the body's record
(postProcessing/fbmBodies/0/<body>.dat: Time Fx Fy Fz Tx Ty Tz x y z Ux Uy
Uz wx wy wz) gives
    steps, t_end       time steps and last time of the record
    max_speed, t_max   largest |U| and when
    Re_max             rho_s max|U| d / nu (the disk: the paper's
                       definition, rho_f = 1)
    speed_0.1, speed_0.15  |U| at the last step at or before t = 0.1, 0.15
    speed_end          |U| at the last step
    y_start, y_end     height of the centre at the first and last step
    bodyCo_max         largest body Courant number |U| dt / h (dt the step
                       that ends at the row, U its end velocity)
    a_first            the first step's acceleration |U_y|/t of the first
                       row
    cpu_s              fbmFoam's last ExecutionTime
    status             exitStatus of the tutorial's Allrun (0: done)
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

# body file, rho_s, diameter, nu, cell size h
BODIES = {
    "disk": ("particle", 1.5, 0.25, 0.1, 2.0/48),
    "neutral": ("particle", 1.01, 0.25, 0.1, 2.0/48),
    "sphere": ("sphere", 1.5, 0.1, 0.1, 0.5/40),
}
COLUMNS = ["run", "body", "coupling", "maxBodyCo", "deltaT", "cells",
           "steps", "t_end", "max_speed", "t_max", "Re_max", "speed_0.1",
           "speed_0.15", "speed_end", "y_start", "y_end", "bodyCo_max",
           "a_first", "cpu_s", "status"]
ORDER = ["disk-explicit", "disk-projection", "disk-projection-maxBodyCo0.1",
         "disk-projection-dt2e-4", "sphere-explicit", "sphere-projection",
         "sphere-projection-maxBodyCo0.1", "sphere-semiImplicit",
         "sphere-semiImplicit-dt5e-4", "sphere-semiImplicit-ratio5",
         "sphere-semiImplicit-ratio8", "sphere-semiImplicit-ratio12",
         "neutral-L3",
         "neutral-L4", "neutral-L5"]


def lastMatch(path, pattern):
    value = ""
    with open(path, errors="replace") as f:
        for line in f:
            m = re.search(pattern, line)
            if m:
                value = m.group(1)
    return value


def collectRun(run):
    name = os.path.basename(run)
    body = name.split("-")[0]
    bodyFile, rho, d, nu, h = BODIES[body]
    m = re.search(r"^level\s+(\d+);", open(os.path.join(
        run, "system/caseParameters")).read(), re.M) \
        if body in ("disk", "neutral") else None
    if m:
        h = 2.0/(12*2**(int(m.group(1)) - 1))
    rows, t, speed = fbmOutput.bodyRecord(run, bodyFile)
    iMax = max(range(len(rows)), key=lambda i: speed[i])
    co = fbmOutput.largestBodyCourant(t, speed, h)

    def at(time):
        return fbmOutput.speedAt(t, speed, time)

    props = open(os.path.join(run, "constant/fbmProperties")).read()
    control = open(os.path.join(run, "system/controlDict")).read()
    m = re.search(r"^coupling\s+(\w+)\s*;", props, re.M)
    coupling = m.group(1) if m else "explicit"
    m = re.search(r"^maxBodyCo\s+([^;\s]+);", props, re.M)
    maxBodyCo = m.group(1) if m else ""
    fixed = re.search(r"^adjustTimeStep\s+no;", control, re.M)
    deltaT = re.search(r"^deltaT\s+([^;\s]+);", control, re.M).group(1) \
        if fixed else "maxCo"
    cells = lastMatch(os.path.join(run, "log.blockMesh"), r"nCells:\s*(\d+)")
    cpu = lastMatch(os.path.join(run, "log.fbmFoam"),
                    r"^ExecutionTime = ([0-9.e+-]+) s")
    try:
        status = open(os.path.join(run, "exitStatus")).read().strip()
    except OSError:
        status = "none"
    return {"run": name, "body": body, "coupling": coupling,
            "maxBodyCo": maxBodyCo, "deltaT": deltaT, "cells": cells,
            "steps": len(rows), "t_end": "%.6g" % t[-1],
            "max_speed": "%.5g" % speed[iMax], "t_max": "%.4g" % t[iMax],
            "Re_max": "%.5g" % (rho*speed[iMax]*d/nu),
            "speed_0.1": at(0.1), "speed_0.15": at(0.15),
            "speed_end": "%.5g" % speed[-1], "y_start": "%.5g" % rows[0][8],
            "y_end": "%.5g" % rows[-1][8], "bodyCo_max": "%.3g" % co,
            "a_first": "%.5g" % (abs(rows[0][11])/rows[0][0]),
            "cpu_s": "%.2f" % float(cpu) if cpu else "", "status": status}


def main():
    runs = [r for r in glob.glob(os.path.join(HERE, "runs", "*"))
            if os.path.basename(r) in ORDER]
    # The rows of runs not in runs/ stay as they are in results.csv
    results = {os.path.basename(r): collectRun(r) for r in runs}
    path = os.path.join(HERE, "results.csv")
    if os.path.isfile(path):
        for row in csv.DictReader(open(path)):
            if row["run"] in ORDER and row["run"] not in results:
                results[row["run"]] = row
    results = [results[n] for n in ORDER if n in results]
    with open(os.path.join(HERE, "results.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, COLUMNS, lineterminator="\n")
        w.writeheader()
        w.writerows(results)
    for r in results:
        print(",".join(str(r[c]) for c in COLUMNS))
    print("Wrote results.csv")


if __name__ == "__main__":
    main()
