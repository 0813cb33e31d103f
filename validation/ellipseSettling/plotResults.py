#!/usr/bin/python3
"""Analyse the settling-ellipse runs in runs/ (see Allrun).

An ellipse (a = 0.1, b = 0.05, rho_s/rho_f = 1.1) settles from rest in a
channel 0.8 wide (blockage 2a/L = 0.25), released on the centre line with
its major axis at 45 degrees. For each run, the history of the centre
(x, y), the settling velocity -Uy and the angle theta of the major axis to
the horizontal (degrees, wrapped to (-90, 90]):

- fbmFoam runs (fbm-*): postProcessing/fbmBodies/0/ellipse.dat (theta =
  45 degrees + the accumulated rotation `angle`);
- body-fitted runs (bodyFitted-*): the sixDoF report of each stage's log
  (log.pimpleFoam.NN: Centre of rotation, Orientation, Linear velocity;
  theta = 45 degrees + atan2(Q_yx, Q_xx)).

The history is cut where the centre comes within yCut = 0.6 (6 a) of the
bottom wall (the wall's effect; no contact model). The late window is the
last 40 % of the time left (the start-up left out).
Over it: the terminal settling velocity U_t (mean of -Uy), the Reynolds
numbers Re = U_t 2a/nu (major axis, Xia et al.'s definition as far as
could be checked, README.md) and U_t a/nu; the mean and half the peak-to-
peak range of theta and of x; the period of the lateral oscillation (twice
the mean spacing of the crossings of x through its window mean; blank with
fewer than three crossings); the last four swings of theta (the largest
|theta| between successive crossings of 0) and the ratio of the last two
(peak_ratio: > 1 a growing swing, < 1 a decaying one). The
mode: "oscillating" when x swings by more than 0.1 a or theta by more than
5 degrees (half range) and the swing holds (peak_ratio >= 0.95);
"undecided" when it swings so and decays slowly (0.8 <= peak_ratio <
0.95: the channel is too short to tell); else "horizontal" when |mean
theta| < 5 degrees or the swing about it decays fast ("damped swing" added
while the half range is still above 1 degree), "vertical" (|theta| > 85)
or "inclined". CPU:
the solver's last ExecutionTime (each stage's, summed, for the body-fitted
runs, plus reReference.py's CPU).

Also, for the comparison of the solvers: the time t_theta0 at which theta
first crosses 0 (linear interpolation), the first extremum of theta after
it (theta_overshoot) and the largest settling velocity Umax (before the
cut). A run that did not reach its endTime is a row marked failed and is
left out of the chart.

For a body-fitted run t_sound is where its flow breaks down on the
morphing mesh (the first step after t = 0.05 whose largest Courant number
is more than twice the smallest of the 0.02 s before it; the steps are
capped, so it changes slowly while the run is sound); the chart shows it up
to there, and comparison.csv gives, at each viscosity with a body-fitted
run, every fbmFoam and body-fitted run (not the -explicit variant) every
0.05 s up to the earliest t_sound (or end) of them. Runs *-short stop at
t = 0.4 (the first turn): no terminal values in table.md.

Only runs that have been run to their end (runs/RUN/runDone, written by
Allrun) are analysed. Writes results.csv, history.csv (every run's history, 0.01 s apart, up to
the cut), comparison.csv, table.md and settling.png. The rows of a run
analysed before whose case is not in runs/ (runs/ is not in git) are kept
as they are in these files, and the chart draws it from history.csv.
"""
import csv
import glob
import math
import os
import re

import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

a, b = 0.1, 0.05
theta0 = 45.0
xMid = 0.4
window = 0.4
yCut = 0.6


def wrap(theta):
    """Degrees to (-90, 90] (an ellipse is symmetric under 180 degrees)."""
    return 90.0 - np.mod(90.0 - theta, 180.0)


def parameter(case, name, fname="system/caseParameters"):
    text = open(os.path.join(case, fname)).read()
    m = re.search(r"^%s\s+([^;]+);" % name, text, re.M)
    return m.group(1).strip() if m else None


def cells(case):
    logs = sorted(glob.glob(os.path.join(case, "log.checkMesh*")))
    for f in logs + [os.path.join(case, "log.blockMesh")]:
        if os.path.exists(f):
            m = re.search(r"cells:\s*(\d+)|nCells:\s*(\d+)", open(f).read())
            if m:
                return int(m.group(1) or m.group(2))
    return 0


def lastCpu(log):
    times = re.findall(r"^ExecutionTime = ([0-9.eE+-]+) s", log, re.M)
    return float(times[-1]) if times else 0.0


def fbmHistory(case):
    d = np.loadtxt(os.path.join(case, "postProcessing/fbmBodies/0/ellipse.dat"))
    t, x, y, uy = d[:, 0], d[:, 7], d[:, 8], d[:, 11]
    theta = theta0 + np.degrees(d[:, -1])
    cpu = lastCpu(open(os.path.join(case, "log.fbmFoam")).read())
    coupling = parameter(case, "coupling", "constant/fbmProperties") or "explicit"
    if coupling == "explicit":
        coupling += ", addedMassCoeff " + parameter(
            case, "addedMassCoeff", "constant/fbmProperties")
    if re.search(r"^\s*extrapolatePredictor\s+yes\s*;", open(os.path.join(
            case, "system/fvSolution")).read(), re.M):
        coupling += "; 1 outer corrector, extrapolatePredictor"
    elif coupling == "semiImplicit":
        n = re.search(r"^\s*nOuterCorrectors\s+(\d+)\s*;", open(os.path.join(
            case, "system/fvSolution")).read(), re.M)
        coupling += "; %s outer corrector%s" % (
            n.group(1), "" if n.group(1) == "1" else "s")
    ddt = re.search(r"ddtSchemes\s*\{\s*default\s+(\w+)\s*;", open(
        os.path.join(case, "system/fvSchemes")).read())
    if ddt and ddt.group(1) != "Euler":
        coupling += "; " + ddt.group(1)
    ratio = re.search(r"maxViscousRatio\s+([0-9.eE+-]+)\s*;", open(
        os.path.join(case, "constant/fbmProperties")).read())
    if ratio:
        coupling += "; maxViscousRatio " + ratio.group(1)
    solve = re.search(r"pressureSolve\s+(\w+)\s*;", open(
        os.path.join(case, "constant/fbmProperties")).read())
    if solve:
        coupling += "; pressureSolve " + solve.group(1)
    return t, x, y, uy, theta, cpu, coupling, t[-1]


vec = r"\(([^()]*)\)"


def bodyFittedHistory(case):
    rows = {}
    cpu = 0.0
    for f in sorted(glob.glob(os.path.join(case, "log.pimpleFoam.*"))):
        log = open(f).read()
        cpu += lastCpu(log)
        for block in re.split(r"\nTime = ", log)[1:]:
            t = float(block.split("\n", 1)[0])
            c = re.search(r"Centre of rotation: " + vec, block)
            q = re.search(r"Orientation: " + vec, block)
            u = re.search(r"Linear velocity: " + vec, block)
            if not (c and q and u):
                continue
            c = [float(v) for v in c.group(1).split()]
            q = [float(v) for v in q.group(1).split()]
            u = [float(v) for v in u.group(1).split()]
            co = re.search(r"Courant Number mean: \S+ max: (\S+)", block)
            co = float(co.group(1)) if co else float("nan")
            # a restarted stage repeats no step: a later one overwrites
            rows[t] = (c[0], c[1], u[1],
                       math.degrees(math.atan2(q[3], q[0])), co)
    f = os.path.join(case, "log.reReference")
    if os.path.exists(f):
        for line in open(f):
            cpu += float(line.split()[-1])
    t = np.array(sorted(rows))
    d = np.array([rows[k] for k in t])
    # Where the flow on the morphing mesh breaks down: the first step after
    # t = 0.05 whose largest Courant number is more than twice the smallest
    # of the 0.02 s before it (the steps are capped, so the Courant number
    # changes slowly while the run is sound)
    co = d[:, 4]
    tSound = t[-1]
    for i in np.nonzero(t > 0.05)[0]:
        before = co[(t >= t[i] - 0.02) & (t < t[i])]
        if len(before) and co[i] > 2*np.min(before):
            tSound = t[i]
            break
    return (t, d[:, 0], d[:, 1], d[:, 2], theta0 + d[:, 3], cpu,
            "sixDoF (Newmark), body-fitted", tSound)


def analyse(run):
    case = os.path.join("runs", run)
    if run.startswith("fbm-"):
        t, x, y, uy, theta, cpu, coupling, tSound = fbmHistory(case)
        solver = "fbmFoam"
    else:
        t, x, y, uy, theta, cpu, coupling, tSound = bodyFittedHistory(case)
        solver = "pimpleFoam"
    nu = float(parameter(case, "nu"))
    level = int(parameter(case, "level"))
    theta = wrap(theta)
    yEnd = y[-1]
    tEnd = t[-1]
    status = os.path.join(case, "runStatus")
    if os.path.exists(status):
        ended = open(status).read().strip() == "endTime"
    else:
        ended = "\nEnd" in open(os.path.join(case, "log.fbmFoam")).read()
    keep = np.arange(len(t)) <= np.nonzero(y >= yCut)[0][-1]
    t, x, y, uy, theta = t[keep], x[keep], y[keep], uy[keep], theta[keep]
    w = t >= t[-1]*(1 - window)
    Ut = -np.mean(uy[w])
    xm = np.mean(x[w])
    xAmp = 0.5*(np.max(x[w]) - np.min(x[w]))
    thMean = np.mean(theta[w])
    thAmp = 0.5*(np.max(theta[w]) - np.min(theta[w]))
    s = np.sign(x[w] - xm)
    tw = t[w]
    cross = tw[1:][s[1:] != s[:-1]]
    period = 2*np.mean(np.diff(cross)) if len(cross) >= 3 else float("nan")
    # The swings of theta about 0: the largest |theta| between successive
    # crossings of 0 (complete half swings only); the ratio of the last
    # two, > 1 growing, < 1 decaying
    cr = np.nonzero(np.sign(theta[1:]) != np.sign(theta[:-1]))[0] + 1
    peaks = np.array([np.max(np.abs(theta[i:j]))
                      for i, j in zip(cr[:-1], cr[1:])])
    ext = np.array([i + np.argmax(np.abs(theta[i:j]))
                    for i, j in zip(cr[:-1], cr[1:])], dtype=int)
    ratio = peaks[-1]/peaks[-2] if len(peaks) >= 2 else float("nan")
    swinging = xAmp > 0.1*a or thAmp > 5
    if swinging and not ratio < 0.95:
        mode = "oscillating"
    elif swinging and not ratio < 0.8:
        mode = "undecided (swing decaying slowly)"
    elif abs(thMean) < 5 or (ratio < 0.8 and abs(thMean) < 5 + thAmp):
        mode = "horizontal" + (" (damped swing)" if thAmp > 1 else "")
    elif abs(thMean) > 85:
        mode = "vertical"
    else:
        mode = "inclined"
    if not ended:
        mode = "failed (stopped at t = %.3g)" % t[-1]
    # The first turn: the time theta first crosses 0 (broad side down) and
    # the first extremum after it (the overshoot)
    i0 = np.nonzero(theta <= 0)[0]
    t0 = float("nan")
    over = float("nan")
    if len(i0) and i0[0] > 0:
        i = i0[0]
        t0 = t[i - 1] + theta[i - 1]/(theta[i - 1] - theta[i])*(t[i] - t[i - 1])
        if len(ext):
            over = theta[ext[0]]
    row = dict(run=run, solver=solver, coupling=coupling, nu=nu,
               level=level, cells=cells(case), t_end=tEnd, t_sound=tSound,
               t_cut=t[-1], y_end=yEnd,
               window_from=t[-1]*(1 - window), Ut=Ut, Re_2a=Ut*2*a/nu,
               Re_a=Ut*a/nu, theta_mean=thMean, theta_amp=thAmp,
               x_mean=xm, x_offset_a=(xm - xMid)/a, x_amp=xAmp,
               x_amp_a=xAmp/a, period=period,
               theta_peaks=" ".join("%.1f" % p for p in peaks[-4:]),
               peak_ratio=ratio, t_theta0=t0, theta_overshoot=over,
               Umax=np.max(-uy), mode=mode,
               ended="yes" if ended else "no", cpu_s=cpu)
    return row, (t, x, y, uy, theta, tSound)


runs = sorted(os.path.basename(c) for c in glob.glob("runs/*")
              if os.path.exists(os.path.join(c, "runDone")) and (
                  glob.glob(os.path.join(c, "postProcessing/fbmBodies/0/ellipse.dat"))
                  or glob.glob(os.path.join(c, "log.pimpleFoam.*"))))
rows, hist = [], {}
for run in runs:
    try:
        row, h = analyse(run)
    except (OSError, ValueError, IndexError) as e:
        print(f"{run}: skipped ({e})")
        continue
    rows.append(row)
    hist[run] = h

# Runs of a previous analysis whose case is not here (runs/ is not in git,
# ./Allrun RUN runs one): their rows in results.csv, history.csv,
# comparison.csv and table.md are kept as they are, and the chart draws
# them from history.csv (0.01 s apart)


def previous(fname):
    if not os.path.exists(fname):
        return [], []
    lines = list(csv.reader(open(fname, newline="")))
    return (lines[0], lines[1:]) if lines else ([], [])


analysed = {r["run"] for r in rows}
resHead, resOld = previous("results.csv")
kept = {line[0]: dict(zip(resHead, line)) for line in resOld
        if line and line[0] not in analysed}
histOld = [line for line in previous("history.csv")[1]
           if line and line[0] in kept]
cmpOld = [line for line in previous("comparison.csv")[1]
          if line and line[0] in kept]
tableOld = {}
if os.path.exists("table.md"):
    for line in open("table.md"):
        cell = line.split("|")[1].strip() if line.startswith("| ") else ""
        if cell in kept:
            tableOld[cell] = line

fmt = dict(nu="{:g}", t_end="{:.4g}", t_sound="{:.4g}", t_cut="{:.4g}", y_end="{:.4f}", window_from="{:.4g}",
           Ut="{:.4f}", Re_2a="{:.2f}", Re_a="{:.2f}", theta_mean="{:.2f}",
           theta_amp="{:.2f}", x_mean="{:.4f}", x_offset_a="{:.3f}",
           x_amp="{:.4f}", x_amp_a="{:.3f}", period="{:.3f}",
           peak_ratio="{:.3f}", t_theta0="{:.4f}",
           theta_overshoot="{:.2f}", Umax="{:.4f}", cpu_s="{:.0f}")
with open("results.csv", "w", newline="") as f:
    wr = csv.writer(f)
    keys = list(rows[0].keys()) if rows else resHead
    wr.writerow(keys)
    lines = {r["run"]: [("" if isinstance(r[k], float) and math.isnan(r[k])
                         else fmt[k].format(r[k])) if k in fmt else r[k]
                        for k in keys] for r in rows}
    lines.update({run: [k_.get(k, "") for k in keys]
                  for run, k_ in kept.items()})
    for run in sorted(lines):
        wr.writerow(lines[run])

with open("history.csv", "w", newline="") as f:
    wr = csv.writer(f)
    wr.writerow(["run", "t", "x", "y", "Uy", "theta"])
    lines = {run: [line for line in histOld if line[0] == run]
             for run in kept}
    for run, (t, x, y, uy, theta, ts) in hist.items():
        lines[run] = []
        for tt in np.arange(0, t[-1] + 1e-9, 0.01):
            i = min(np.searchsorted(t, tt), len(t) - 1)
            lines[run].append([run, "%.2f" % tt, "%.5f" % x[i],
                               "%.5f" % y[i], "%.5f" % uy[i],
                               "%.3f" % theta[i]])
    for run in sorted(lines):
        wr.writerows(lines[run])

# The solvers side by side at the same times: at each viscosity that has a
# body-fitted run (the -explicit variant left out), every fbmFoam and
# body-fitted run, every 0.05 s up to the earliest t_sound of them
with open("comparison.csv", "w", newline="") as f:
    wr = csv.writer(f)
    wr.writerow(["run", "t", "x", "y", "U", "theta"])
    # (a body-fitted run kept from a previous analysis counts with its
    # t_sound and t_end from results.csv, its rows with cmpOld)
    for nuText in sorted({r.split("-")[1] for r in list(hist) + list(kept)
                          if r.startswith("bodyFitted-")}):
        group = [r for r in hist if r.split("-")[1] == nuText
                 and not r.endswith("-explicit")]
        keptGroup = [r for r in kept if r.split("-")[1] == nuText
                     and not r.endswith("-explicit")]
        tMax = min([min(hist[r][5], hist[r][0][-1]) for r in group]
                   + [min(float(kept[r]["t_sound"]), float(kept[r]["t_end"]))
                      for r in keptGroup])
        for run in group:
            t, x, y, uy, theta, ts = hist[run]
            for tt in np.arange(0.05, tMax + 1e-9, 0.05):
                xi = lambda v: np.interp(tt, t, v)
                wr.writerow([run, "%.2f" % tt, "%.4f" % xi(x),
                             "%.4f" % xi(y), "%.4f" % -xi(uy),
                             "%.2f" % xi(theta)])
    wr.writerows(cmpOld)

with open("table.md", "w") as f:
    f.write("| run | coupling | cells | U_t | Re (2a) | theta [deg] "
            "| x - L/2 [a] | x swing [a] | period | mode | CPU [s] |\n")
    f.write("|---|---|---|---|---|---|---|---|---|---|---|\n")
    table = dict(tableOld)
    for r in rows:
        if r["ended"] == "no" or r["run"].endswith("-short"):
            note = (r["mode"] if r["ended"] == "no" else
                    "the %s only (endTime %.3g)" % (
                        "first turn" if r["t_end"] <= 0.5 else "start",
                        r["t_end"]))
            table[r["run"]] = (
                "| %s | %s | %s | - | - | - | - | - | - | %s; sound to "
                "t = %.3g | %.0f |\n" % (
                    r["run"], r["coupling"], f"{r['cells']:,}",
                    note, r["t_sound"], r["cpu_s"]))
            continue
        table[r["run"]] = (
            "| %s | %s | %s | %.3f | %.1f | %.1f ± %.1f | %.2f | %.2f "
            "| %s | %s | %.0f |\n" % (
                    r["run"], r["coupling"], f"{r['cells']:,}", r["Ut"],
                    r["Re_2a"], r["theta_mean"], r["theta_amp"],
                    r["x_offset_a"], r["x_amp_a"],
                    "" if math.isnan(r["period"]) else "%.2f" % r["period"],
                    r["mode"], r["cpu_s"]))
    for run in sorted(table):
        f.write(table[run])

# Chart: trajectory, angle and settling velocity against time, and the
# first turn of the runs at the viscosity of the body-fitted runs
fig, ax = plt.subplots(1, 4, figsize=(18, 5.5),
                       gridspec_kw=dict(width_ratios=[1, 2, 2, 2]))
drawn = dict(hist)
for run, k_ in kept.items():
    h = np.array([[float(v) for v in line[1:]] for line in histOld
                  if line[0] == run])
    if len(h):
        drawn[run] = (h[:, 0], h[:, 1], h[:, 2], h[:, 3], h[:, 4],
                      float(k_["t_sound"]))
for run, (t, x, y, uy, theta, ts) in sorted(drawn.items()):
    if run.endswith("-explicit") or run.endswith("-short"):
        continue
    # body-fitted runs: up to the breakdown of the flow (t_sound)
    k = t <= ts
    t, x, y, uy, theta = t[k], x[k], y[k], uy[k], theta[k]
    style = "-" if run.startswith("fbm-") else "--"
    ax[0].plot(x, y, style, lw=1, label=run)
    ax[1].plot(t, theta, style, lw=1, label=run)
    ax[2].plot(t, -uy, style, lw=1, label=run)
ax[0].set_xlim(0, 0.8)
ax[0].set_aspect("equal")
ax[0].set_xlabel("x [cm] (channel 0.8)")
ax[0].set_ylabel("y [cm]")
ax[0].set_title("trajectory")
ax[1].axhline(0, color="k", lw=0.5)
ax[1].set_xlabel("t [s]")
ax[1].set_ylabel("angle of the major axis to the horizontal [deg]")
ax[1].set_title("orientation (0: broad side down)")
ax[2].set_xlabel("t [s]")
ax[2].set_ylabel("settling velocity -U_y [cm/s]")
ax[2].set_title("settling velocity")
ax[1].legend(fontsize=7)
# The first turn: every run with a body-fitted partner, up to its t_sound
cmp = {}
for row in csv.DictReader(open("comparison.csv")):
    cmp.setdefault(row["run"], []).append(row)
tw = ax[3].twinx()
for run, rs in cmp.items():
    style = "-" if run.startswith("fbm-") else "--"
    tt = [float(r["t"]) for r in rs]
    ax[3].plot(tt, [float(r["theta"]) for r in rs], style + "o", ms=3,
               lw=1, label=run)
    tw.plot(tt, [float(r["U"]) for r in rs], style + "s", ms=3, lw=1,
            alpha=0.5)
ax[3].set_xlabel("t [s]")
ax[3].set_ylabel("angle [deg] (circles)")
tw.set_ylabel("settling velocity [cm/s] (squares, faint)")
ax[3].set_title("fbmFoam against body-fitted: the first turn")
ax[3].legend(fontsize=7, loc="lower left")
modes = "; ".join(f"{r['run']}: {r['mode']}" for r in
                  sorted(rows + list(kept.values()), key=lambda r: r["run"])
                  if r["run"].startswith("fbm-")
                  and not r["run"].endswith("-short"))
fig.suptitle("Ellipse a/b = 2, rho_s/rho_f = 1.1, 2a/L = 0.25 (after Xia "
             "et al. 2009: nu = 0.028284 is their validation case, "
             "xia.png; their regime map could not be retrieved, "
             "README.md). Mode found: " + modes, fontsize=8)
fig.tight_layout()
fig.savefig("settling.png", dpi=110)
print(open("table.md").read())
