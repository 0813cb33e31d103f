#!/usr/bin/python3
"""Collect, tabulate and plot the settling-disk mesh study of fbmFoam.

The paper's "A circular particle settling" (Table 2, Fig. 9-10): a disk of
radius R = 0.125 (d = 0.25) released from rest at (1, 4) in a 2 x 6 channel,
rho_f = 1, g = 980, nu = 0.1 or 0.01, rho_s = 1.25 or 1.5 (cgs units).

With --collect, reads every run in runs/<case>-L<level>/ (made by ./Allrun:
postProcessing/fbmBodies/0/particle.dat, log.blockMesh, log.fbmFoam,
exitStatus) and writes

    results.csv    case,nu,rho_s,cells,Re_max,Re_f_max,wall_s: one row per
                   case and level (case named e.g. nu0.1-rho1.5-L4)
    runInfo.csv    how each run ended, where its maximum is, how much its
                   velocity oscillates, how symmetric it stays

Then (always) reads results.csv, runInfo.csv and validationData/ and writes

    table.md       Re_max per case and level beside the body-fitted OpenFOAM
                   values and the paper's (Table 2), errors in % against the
                   finest body-fitted value, and how each run ended

and, from the histories in runs/ (skipped when runs/ is absent):

    settling.png   v(t) and y(t) of nu = 0.1, rho_s = 1.5, all levels
                   (the paper's Fig. 9)
    energy.png     translational 0.5 M |U|^2 and rotational 0.5 I w^2
                   kinetic energy per unit depth (M = rho_s pi R^2,
                   I = 0.5 M R^2) of the same runs (the paper's Fig. 10)
    reynolds.png   Re(t) = rho_s |U| d / mu of the four cases at the finest
                   level run (coarser levels thin and light)

The charts show each record up to the bottom wall, or up to where the disk
first moves up again near it (it bounces off: no contact model).

Re_max is the maximum over the record while the particle is at least one
diameter away from every wall (gap = distance of its surface to the wall
>= d). Closer to the bottom there is no contact model and the explicit
coupling oscillates and runs away (the run stops with 'exceeds maxSpeed' or
ends when the disk leaves the domain); runInfo.csv gives the maximum over
the whole record too.

Usage:
    plotResults.py [-h] [--collect] [--check]

--check exits with status 1 unless, for every case, the finest level run is
within TOLERANCE of the finest body-fitted Re_max and differs from the next
coarser level by less than that tolerance.

Run it with Debian's python3 (/usr/bin/python3, python3-matplotlib).
"""

import argparse
import csv
import math
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, "validationData")
RUNS = os.path.join(HERE, "runs")

# The case (cgs units)
RADIUS = 0.125
DIAMETER = 2*RADIUS
RHO_F = 1.0
WIDTH, HEIGHT = 2.0, 6.0

# The four cases in the paper's order (Table 2)
CASES = ("nu0.1-rho1.25", "nu0.1-rho1.5", "nu0.01-rho1.25", "nu0.01-rho1.5")

# The case of the paper's Fig. 9 and 10
FIGURE_CASE = "nu0.1-rho1.5"

# Accepted |error| in % of Re_max against the finest body-fitted value
# (acceptance of the validation issue), by nu
TOLERANCE = {0.1: 3.0, 0.01: 5.0}

# Records closer than this to a wall are left out of Re_max
WALL_GAP = DIAMETER

RESULTS_HEADER = ["case", "nu", "rho_s", "cells", "Re_max", "Re_f_max", "wall_s",
                  "cpu_s"]
INFO_HEADER = [
    "case", "addedMassCoeff", "maxSpeed", "exit", "end", "t_end", "bottom_gap_end_d",
    "t_max", "y_max", "bottom_gap_max_d", "Re_max_all", "t_max_all",
    "bottom_gap_max_all_d",
    "osc_pct", "t_osc", "x_drift_max", "omega_max", "drag_noise_pct",
]


def parseCase(name):
    """(case, nu, rho_s, level) of nu<NU>-rho<RHO>[-L<level>]"""
    m = re.fullmatch(r"nu([0-9.eE+-]+)-rho([0-9.eE+-]+)(?:-L([0-9]+))?", name)
    if not m:
        return None
    level = int(m.group(3)) if m.group(3) else None
    return ("nu%s-rho%s" % (m.group(1), m.group(2)), float(m.group(1)),
            float(m.group(2)), level)


def caseOrder(case):
    return CASES.index(case) if case in CASES else len(CASES)


def readCsv(path):
    """Rows of a csv file as dicts; lines starting with '#' are comments"""
    with open(path) as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


def readHistory(run):
    """Columns of particle.dat: t, x, y, Ux, Uy, wz (lists)"""
    path = os.path.join(run, "postProcessing", "fbmBodies", "0", "particle.dat")
    h = {k: [] for k in ("t", "Fy", "x", "y", "Ux", "Uy", "wz")}
    with open(path) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            v = [float(s) for s in line.split()]
            if len(v) < 16:
                continue
            for k, i in (("t", 0), ("Fy", 2), ("x", 7), ("y", 8), ("Ux", 10),
                         ("Uy", 11), ("wz", 15)):
                h[k].append(v[i])
    h["speed"] = [math.hypot(u, v) for u, v in zip(h["Ux"], h["Uy"])]
    h["gap"] = [min(x - RADIUS, WIDTH - x - RADIUS, y - RADIUS, HEIGHT - y - RADIUS)
                for x, y in zip(h["x"], h["y"])]
    # Index of the first record closer than WALL_GAP to a wall: the valid
    # part of the record is [0, nValid)
    h["nValid"] = next((i for i, g in enumerate(h["gap"]) if g < WALL_GAP),
                       len(h["t"]))
    # Records shown in the charts: up to the wall, or to where the disk
    # first moves up again near it (it bounces off: no contact model)
    h["nPlot"] = next((i + 1 for i in range(h["nValid"], len(h["t"]) - 1)
                       if h["y"][i + 1] > h["y"][i]), len(h["t"]))
    for k in ("t", "x", "y", "Ux", "Uy", "wz", "speed", "gap"):
        h[k + "Plot"] = h[k][:h["nPlot"]]
    return h


def runs(runsDir=RUNS):
    """(name, case, nu, rho_s, level, path) of every run in runsDir with data"""
    found = []
    if not os.path.isdir(runsDir):
        return found
    for name in os.listdir(runsDir):
        parsed = parseCase(name)
        path = os.path.join(runsDir, name)
        dat = os.path.join(path, "postProcessing", "fbmBodies", "0", "particle.dat")
        if parsed and parsed[3] is not None and os.path.isfile(dat):
            found.append((name,) + parsed + (path,))
    found.sort(key=lambda r: (caseOrder(r[1]), r[1], r[4]))
    return found


def lastMatch(path, pattern):
    """Group 1 of the last match of pattern in the file (None if none)"""
    value = None
    try:
        with open(path, errors="replace") as f:
            for line in f:
                m = re.search(pattern, line)
                if m:
                    value = m.group(1)
    except OSError:
        pass
    return value


def endOfRun(run):
    """(exit status, how the run ended) from exitStatus and log.fbmFoam; a
    run stopped by hand has a file stoppedByHand that says why"""
    try:
        with open(os.path.join(run, "exitStatus")) as f:
            status = f.read().strip()
    except OSError:
        status = ""
    log = os.path.join(run, "log.fbmFoam")
    if os.path.isfile(os.path.join(run, "stoppedByHand")):
        end = "stopped by hand"
    elif lastMatch(log, r"(exceeds maxSpeed)"):
        end = "maxSpeed"
    elif lastMatch(log, r"(reaches the domain boundary)"):
        end = "boundary"
    elif lastMatch(log, r"(FOAM FATAL)"):
        end = "fatal"
    elif lastMatch(log, r"^(End)\s*$"):
        end = "endTime"
    elif status not in ("", "0"):
        end = "killed"
    else:
        end = "running"
    return status, end


def oscillation(h, n):
    """Largest period-2 (step to step) amplitude of Uy in [1, n - 1):
    |Uy_i - (Uy_i-1 + Uy_i+1)/2|/2 (a for Uy = U0 + a (-1)^i), and its time"""
    best, tBest = 0.0, float("nan")
    Uy = h["Uy"]
    for i in range(1, n - 1):
        a = abs(Uy[i] - 0.5*(Uy[i - 1] + Uy[i + 1]))/2
        if a > best:
            best, tBest = a, h["t"][i]
    return best, tBest


def dragNoise(h, n, uMax, half=10):
    """Grid-crossing noise of the drag near terminal speed: the rms of Fy
    about its centred running mean over 2 half + 1 records, over the
    records of [0, n) with a speed of at least 98 % of uMax, in % of the
    mean drag there ('' when fewer than 2 half + 1 such records)"""
    Fy = h["Fy"]
    idx = [i for i in range(half, n - half) if h["speed"][i] >= 0.98*uMax]
    if len(idx) < 2*half + 1:
        return ""
    dev = [Fy[i] - sum(Fy[i - half:i + half + 1])/(2*half + 1) for i in idx]
    mean = sum(abs(Fy[i]) for i in idx)/len(idx)
    return "%.3g" % (100*math.sqrt(sum(d*d for d in dev)/len(dev))/mean)


def fbmSetting(run, key, default=""):
    """A top-level setting of the run's constant/fbmProperties (as written)"""
    value = lastMatch(os.path.join(run, "constant", "fbmProperties"),
                      r"^\s*%s\s+([^;\s]+)\s*;" % key)
    return value or default


def caseKey(row):
    """Sort key of a csv row, the order runs() lists its runs in"""
    parsed = parseCase(row[0])
    if not parsed or parsed[3] is None:
        return (1e9, row[0], 0)
    return (caseOrder(parsed[0]), parsed[0], parsed[3])


def collect(runsDir=RUNS, suffix=""):
    """Write results<suffix>.csv and runInfo<suffix>.csv from runsDir"""
    results, info = [], []
    for name, case, nu, rho, level, path in runs(runsDir):
        h = readHistory(path)
        n = h["nValid"]
        if n == 0:
            continue
        mu = RHO_F*nu
        iMax = max(range(n), key=lambda i: h["speed"][i])
        iAll = max(range(len(h["t"])), key=lambda i: h["speed"][i])
        uMax = h["speed"][iMax]
        cells = lastMatch(os.path.join(path, "log.blockMesh"), r"^\s*nCells:\s*(\d+)")
        wall = lastMatch(os.path.join(path, "log.fbmFoam"), r"ClockTime = ([0-9.]+) s")
        cpu = lastMatch(os.path.join(path, "log.fbmFoam"), r"ExecutionTime = ([0-9.]+) s")
        status, end = endOfRun(path)
        osc, tOsc = oscillation(h, n)
        results.append([
            name, "%g" % nu, "%g" % rho, cells or "",
            "%.4g" % (rho*uMax*DIAMETER/mu), "%.4g" % (uMax*DIAMETER/nu), wall or "",
            "%.1f" % float(cpu) if cpu else "",
        ])
        info.append([
            name, fbmSetting(path, "addedMassCoeff", "0"),
            fbmSetting(path, "maxSpeed", "1e3"), status, end, "%.4g" % h["t"][-1],
            "%.3g" % ((h["y"][-1] - RADIUS)/DIAMETER),
            "%.4g" % h["t"][iMax], "%.4g" % h["y"][iMax],
            "%.3g" % ((h["y"][iMax] - RADIUS)/DIAMETER),
            "%.4g" % (rho*h["speed"][iAll]*DIAMETER/mu), "%.4g" % h["t"][iAll],
            "%.3g" % ((h["y"][iAll] - RADIUS)/DIAMETER),
            "%.2g" % (100*osc/uMax), "%.3g" % tOsc,
            "%.2g" % max(abs(x - 0.5*WIDTH) for x in h["x"][:n]),
            "%.2g" % max(abs(w) for w in h["wz"][:n]),
            dragNoise(h, n, uMax),
        ])
    # The rows of the existing files whose run is not in runsDir stay as
    # they were (a rerun of some levels or cases keeps the others)
    done = {r[0] for r in results}
    kept = []
    for file, rows in (("results%s.csv" % suffix, results),
                       ("runInfo%s.csv" % suffix, info)):
        path = os.path.join(HERE, file)
        if os.path.exists(path):
            with open(path, newline="") as f:
                for old in list(csv.reader(f))[1:]:
                    if old and old[0] not in done:
                        rows.append(old)
                        if file.startswith("results"):
                            kept.append(old[0])
        rows.sort(key=caseKey)
    if kept:
        print("Kept from results%s.csv (not in %s): %s"
              % (suffix, runsDir, " ".join(kept)))
    for file, header, rows in (("results%s.csv" % suffix, RESULTS_HEADER, results),
                               ("runInfo%s.csv" % suffix, INFO_HEADER, info)):
        with open(os.path.join(HERE, file), "w", newline="") as f:
            w = csv.writer(f, lineterminator="\n")
            w.writerow(header)
            w.writerows(rows)
        print("Wrote %s (%d runs)" % (file, len(rows)))


def pct(value, ref):
    return 100*(value - ref)/ref


def fmtErr(value, ref):
    return "%+.1f %%" % pct(value, ref)


def tables(results, info):
    """table.md; returns the list of failed checks"""
    bodyFitted = {r["case"]: r for r in readCsv(os.path.join(DATA, "bodyFitted.csv"))}
    paper = {r["case"]: r for r in readCsv(os.path.join(DATA, "femFbmTable2.csv"))}
    infoBy = {r["case"]: r for r in info}

    byCase = {}
    for r in results:
        case, nu, rho, level = parseCase(r["case"])
        byCase.setdefault(case, []).append((level, r))
    cases = sorted(set(CASES) | set(byCase), key=lambda c: (caseOrder(c), c))
    levels = sorted({lvl for rows in byCase.values() for lvl, _ in rows})

    out = []
    out.append("# Settling disk: maximum Reynolds number\n")
    out.append("Re_max = rho_s max|U_p| d / mu (the paper's Table 2 definition, "
               "mu = rho_f nu), over the record while the disk is at least d "
               "from every wall. In brackets: error against the finest "
               "body-fitted OpenFOAM value (bold). Written by plotResults.py "
               "from results.csv and validationData/.\n")

    def head(cols):
        out.append("| " + " | ".join(cols) + " |")
        out.append("|" + "---|"*len(cols))

    head(["source (cells)"] + ["nu = %s, rho_s = %s" % (parseCase(c)[1], parseCase(c)[2])
                               for c in cases])

    def value(case, get):
        v = get(case)
        ref = bodyFitted.get(case, {}).get("finest")
        if v in (None, ""):
            return "-"
        if ref:
            return "%.4g (%s)" % (float(v), fmtErr(float(v), float(ref)))
        return "%.4g" % float(v)

    for level in levels:
        cellsSet = {r["cells"] for rows in byCase.values() for lvl, r in rows if lvl == level}
        cells = "/".join(sorted(cellsSet)) if cellsSet else "?"
        row = ["fbmFoam level %d (%s, R/h = %g)"
               % (level, cells, RADIUS/(WIDTH/(12*2**(level - 1))))]
        for c in cases:
            r = dict(byCase.get(c, [])).get(level)
            row.append(value(c, lambda _: r["Re_max"] if r else None))
        out.append("| " + " | ".join(row) + " |")
    for key, label in (("cells3840", "body-fitted OpenFOAM (3,840)"),
                       ("cells15360", "body-fitted OpenFOAM (15,360)")):
        out.append("| " + " | ".join(
            [label] + [value(c, lambda c: bodyFitted.get(c, {}).get(key)) for c in cases]
        ) + " |")
    out.append("| " + " | ".join(
        ["**body-fitted, finest**"]
        + ["**%s**" % bodyFitted[c]["finest"] if c in bodyFitted else "-" for c in cases]
    ) + " |")
    for key, label in (("level5", "paper FEM-FBM level 5 (110,592)"),
                       ("level6", "paper FEM-FBM level 6 (442,368)")):
        out.append("| " + " | ".join(
            [label] + [value(c, lambda c: paper.get(c, {}).get(key)) for c in cases]
        ) + " |")

    # Acceptance
    failed = []
    out.append("\n## Acceptance\n")
    out.append("The finest level within the tolerance of the finest body-fitted "
               "value (3 % at nu = 0.1, 5 % at nu = 0.01) and converged: its "
               "change from the next coarser level smaller than that tolerance.\n")
    head(["case", "tolerance", "finest level", "error", "change from coarser level",
          "result"])
    for c in cases:
        rows = sorted(byCase.get(c, []), key=lambda x: x[0])
        nu = parseCase(c)[1]
        tol = TOLERANCE.get(nu)
        ref = bodyFitted.get(c, {}).get("finest")
        if not rows or tol is None or not ref:
            out.append("| %s | - | - | - | - | no data |" % c)
            failed.append(c)
            continue
        level, r = rows[-1]
        re = float(r["Re_max"])
        err = pct(re, float(ref))
        if len(rows) > 1:
            change = pct(re, float(rows[-2][1]["Re_max"]))
            changeText = "%+.1f %% (from level %d)" % (change, rows[-2][0])
        else:
            change = float("nan")
            changeText = "-"
        ok = abs(err) <= tol and abs(change) <= tol
        if not ok:
            failed.append(c)
        out.append("| %s | %g %% | %d | %+.1f %% | %s | %s |"
                   % (c, tol, level, err, changeText, "pass" if ok else "FAIL"))

    # Runs
    out.append("\n## Runs\n")
    out.append("Re_f = max|U_p| d / nu. wall: fbmFoam's wall time (serial, "
               "on a shared machine). C_am: addedMassCoeff (virtual-mass "
               "stabilisation; 0: the plain explicit coupling). "
               "end: endTime, boundary (the disk left the domain), maxSpeed "
               "(FatalError: the explicit coupling ran away at the wall; the "
               "data before it stand; maxSpeed in runInfo.csv), stopped by hand "
               "(runs/<run>/stoppedByHand says why). t, gap at max: time of "
               "Re_max and the gap between the disk and the bottom wall then, "
               "in d. Re_max all: the maximum over the "
               "whole record, wall region included. oscillation: largest "
               "step-to-step (period-2) amplitude of U_y while gap >= d, in % of "
               "max|U_p|. x drift: max abs(x - 1), max w: max abs(w) while gap >= d.\n")
    head(["run", "cells", "Re_max", "Re_f_max", "wall [s]", "C_am", "exit", "end",
          "t end",
          "t at max", "gap at max [d]", "Re_max all", "oscillation", "x drift",
          "max w [1/s]"])
    for r in sorted(results, key=lambda r: (caseOrder(parseCase(r["case"])[0]),
                                            parseCase(r["case"])[3])):
        i = infoBy.get(r["case"], {})
        out.append("| " + " | ".join([
            r["case"], r["cells"], r["Re_max"], r["Re_f_max"], r["wall_s"],
            i.get("addedMassCoeff", ""), i.get("exit", ""), i.get("end", ""), i.get("t_end", ""),
            i.get("t_max", ""), i.get("bottom_gap_max_d", ""), i.get("Re_max_all", ""),
            (i.get("osc_pct", "") + " % at t = " + i.get("t_osc", "")) if i else "",
            i.get("x_drift_max", ""), i.get("omega_max", ""),
        ]) + " |")

    with open(os.path.join(HERE, "table.md"), "w") as f:
        f.write("\n".join(out) + "\n")
    print("Wrote table.md")
    return failed


def finestRuns():
    """{case: (level, path)} of the finest level run of each case (with data
    away from the walls)"""
    finest = {}
    for name, case, nu, rho, level, path in runs():
        if readHistory(path)["nValid"] == 0:
            continue
        if case not in finest or level > finest[case][0]:
            finest[case] = (level, path)
    return finest


def validLimits(series, n, margin=0.1):
    """y limits that show the valid part [0, n) of each series with a margin"""
    lo = min(min(s[:n_]) for s, n_ in zip(series, n))
    hi = max(max(s[:n_]) for s, n_ in zip(series, n))
    pad = margin*(hi - lo or abs(hi) or 1)
    return lo - pad, hi + pad


def plots():
    allRuns = runs()
    if not allRuns:
        print("No runs in %s: charts not made" % RUNS)
        return

    # Fig. 9 and 10: the figure case at all levels
    fig9 = [(level, readHistory(path)) for _, case, _, _, level, path in allRuns
            if case == FIGURE_CASE]
    fig9 = [(level, h) for level, h in fig9 if h["nValid"] > 0]
    rho = parseCase(FIGURE_CASE)[2]
    mass = rho*math.pi*RADIUS**2      # per unit depth
    inertia = 0.5*mass*RADIUS**2
    if fig9:
        fig, (axv, axy) = plt.subplots(1, 2, figsize=(11, 4.2))
        for level, h in fig9:
            axv.plot(h["tPlot"], h["UyPlot"], lw=1, label="level %d" % level)
            axy.plot(h["tPlot"], h["yPlot"], lw=1, label="level %d" % level)
        axv.set_ylim(*validLimits([h["Uy"] for _, h in fig9],
                                  [h["nValid"] for _, h in fig9]))
        axv.set_xlabel("t [s]")
        axv.set_ylabel("vertical velocity v [cm/s]")
        axy.set_xlabel("t [s]")
        axy.set_ylabel("centre height y [cm]")
        axy.axhline(RADIUS, color="0.5", lw=0.8, ls=":")
        axy.axhline(RADIUS + WALL_GAP, color="0.5", lw=0.8, ls="--")
        axy.text(0.02, RADIUS + WALL_GAP, " gap = d", va="bottom", fontsize=8,
                 color="0.4")
        for ax in (axv, axy):
            ax.grid(alpha=0.3)
            ax.legend()
        fig.suptitle("Settling disk, nu = 0.1, rho_s = 1.5 (paper Fig. 9)")
        fig.tight_layout()
        fig.savefig(os.path.join(HERE, "settling.png"), dpi=120)
        plt.close(fig)

        fig, (axt, axr) = plt.subplots(1, 2, figsize=(11, 4.2))
        for level, h in fig9:
            et = [0.5*mass*s**2 for s in h["speedPlot"]]
            er = [0.5*inertia*w**2 for w in h["wzPlot"]]
            h["et"], h["er"] = et, er
            axt.plot(h["tPlot"], et, lw=1, label="level %d" % level)
            axr.plot(h["tPlot"], er, lw=1, label="level %d" % level)
        axt.set_ylim(*validLimits([h["et"] for _, h in fig9],
                                  [h["nValid"] for _, h in fig9]))
        axr.set_ylim(*validLimits([h["er"] for _, h in fig9],
                                  [h["nValid"] for _, h in fig9]))
        axt.set_ylabel("0.5 M |U|^2 [erg/cm]")
        axr.set_ylabel("0.5 I w^2 [erg/cm]")
        for ax in (axt, axr):
            ax.set_xlabel("t [s]")
            ax.grid(alpha=0.3)
            ax.legend()
        fig.suptitle("Settling disk, nu = 0.1, rho_s = 1.5: kinetic energy per "
                     "unit depth, M = rho_s pi R^2, I = M R^2/2 (paper Fig. 10)")
        fig.tight_layout()
        fig.savefig(os.path.join(HERE, "energy.png"), dpi=120)
        plt.close(fig)

    # Re(t) of the four cases at their finest level (coarser levels thin)
    bodyFitted = {r["case"]: r for r in readCsv(os.path.join(DATA, "bodyFitted.csv"))}
    finest = finestRuns()
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    for ax, nu in zip(axes, (0.1, 0.01)):
        shown, counts = [], []
        cases = [c for c in sorted(finest, key=lambda c: (caseOrder(c), c))
                 if parseCase(c)[1] == nu]
        for k, case in enumerate(cases):
            _, cnu, crho, _ = parseCase(case)
            color = "C%d" % k
            for _, rcase, _, _, level, path in allRuns:
                if rcase != case or level > finest[case][0]:
                    continue
                h = readHistory(path)
                re = [crho*s*DIAMETER/(RHO_F*cnu) for s in h["speedPlot"]]
                if level == finest[case][0]:
                    ax.plot(h["tPlot"], re, color=color, lw=1.2,
                            label="rho_s = %g, level %d" % (crho, level))
                    shown.append(re)
                    counts.append(h["nValid"])
                else:
                    ax.plot(h["tPlot"], re, color=color, lw=0.7, alpha=0.4,
                            label="rho_s = %g, level %d" % (crho, level))
            if case in bodyFitted:
                ax.axhline(float(bodyFitted[case]["finest"]), color=color,
                           ls="--", lw=0.8)
        if shown:
            ax.set_ylim(0, validLimits(shown, counts)[1])
        ax.set_title("nu = %g (dashed: body-fitted Re_max)" % nu)
        ax.set_xlabel("t [s]")
        ax.set_ylabel("Re = rho_s |U| d / mu")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "reynolds.png"), dpi=120)
    plt.close(fig)
    print("Wrote settling.png, energy.png, reynolds.png")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--collect", action="store_true",
                        help="write results.csv and runInfo.csv from runs/ first")
    parser.add_argument("--runs", default=RUNS,
                        help="with --collect: the folder of the runs (default runs/)")
    parser.add_argument("--suffix", default="",
                        help="with --collect: write results<SUFFIX>.csv and "
                        "runInfo<SUFFIX>.csv, and stop there")
    parser.add_argument("--check", action="store_true",
                        help="exit 1 unless every case passes the acceptance")
    args = parser.parse_args()

    if args.collect:
        collect(os.path.abspath(args.runs), args.suffix)
        if args.suffix:
            return 0
    results = readCsv(os.path.join(HERE, "results.csv"))
    infoPath = os.path.join(HERE, "runInfo.csv")
    info = readCsv(infoPath) if os.path.isfile(infoPath) else []
    failed = tables(results, info)
    plots()
    if args.check:
        if failed:
            print("Acceptance failed: " + " ".join(failed))
            return 1
        print("Acceptance passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
