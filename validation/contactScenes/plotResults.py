#!/usr/bin/python3
"""Analyse the contact scenes in runs/ (see Allrun).

Bodies coming to rest on the floor (scenes drop2D*, drop3D, stl*), one
row per body in results.csv:
  the body's height (centre y) and the gap of its lowest point above the
  floor (y less the support of the shape along -y, from its orientation);
  its tilt from the stable orientation: in 2D the angle of the long axis
  (the body's x axis) from the floor; for the box the angle of the body
  axis nearest the vertical from the vertical (the face down is named);
  for the ellipsoid the angle of its shortest axis from the vertical (and
  of its long axis from the floor); |U| and |omega| R (R the bounding
  radius) at the end; the landing time (first step with the lowest point
  within the range of the wall force); the settling time (from which
  |U| + |omega| R stays below 1 % of its largest value); the smallest gap
  of the lowest point over the output steps, and the smallest wall gap of
  the scene over the contact sub-steps (summary.dat, all its bodies);
  the gap at which the wall law carries the submerged weight (gap_law);
  CPU (the solver's last ExecutionTime).

Collisions (scenes headOn*, oblique, dem), one row per run in
collisions.csv: linear momentum P = sum m U and angular momentum about the
fixed point O = (0, 0) (the corner of the box), L = sum m (X - O) x U +
I omega (z component), before (the first output step, before contact) and
after (the last), and the kinetic energy ratio after/before. The fbmFoam
runs have a fluid 250,000 to 1,000,000 times lighter than the bodies: its
force and torque (the body files' F and T) are integrated over the run
(the force of a step acts over the next one, as the explicit coupling
moves the bodies with the last step's force; its moment about O with the
lever arm, and its work with the velocities, at the middle of that step)
and shown beside the change; what the fluid does not account for is the
contacts' share. The dem rows (Test-convexDistance, no fluid): it prints
only the largest |dP| and |dL| (about its origin) over the run and the
energy ratio. Masses: rho pi a b times the mesh depth 0.1 (2D),
rho 4/3 pi a b c (3D); I = m (a^2 + b^2)/4 about the ellipse's centre.

Writes results.csv, collisions.csv, table.md, settling.png and
collisions.png.
"""
import csv
import math
import os
import re

import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

runs = "runs"
rangeWall = 0.05      # range of the wall force in the settling scenes
g = 9.81


def rows(path):
    head = None
    data = []
    for line in open(path):
        if line.startswith("#"):
            if line.startswith("# Time"):
                head = line[1:].split()
            continue
        data.append([float(x) for x in line.split()])
    a = np.array(data)
    return {k: a[:, i] for i, k in enumerate(head)}


def cpu(case):
    log = os.path.join(case, "log.fbmFoam")
    if not os.path.exists(log):
        return float("nan")
    times = re.findall(r"^ExecutionTime = ([0-9.eE+-]+) s", open(log).read(), re.M)
    return float(times[-1]) if times else float("nan")


def cells(case):
    log = os.path.join(case, "log.blockMesh")
    m = re.search(r"nCells:\s*(\d+)", open(log).read()) if os.path.exists(log) else None
    return int(m.group(1)) if m else 0


def rot(q):
    w, x, y, z = q
    return np.array(
        [[1 - 2*(y*y + z*z), 2*(x*y - w*z), 2*(x*z + w*y)],
         [2*(x*y + w*z), 1 - 2*(x*x + z*z), 2*(y*z - w*x)],
         [2*(x*z - w*y), 2*(y*z + w*x), 1 - 2*(x*x + y*y)]])


def settleTimes(t, speed, gap):
    land = t[np.argmax(gap < rangeWall)] if np.any(gap < rangeWall) else float("nan")
    above = np.nonzero(speed > 0.01*speed.max())[0]
    settle = t[above[-1] + 1] if len(above) and above[-1] + 1 < len(t) else float("nan")
    return land, settle


# ---- Bodies coming to rest ---------------------------------------------------
# (scene, body, kind, shape data, start angle (2D), label)
restBodies = [
    ("drop2D", "rectangle", "rect2D", (0.15, 0.06), math.pi/6, "rectangle 0.3 x 0.12 (2D)"),
    ("drop2D", "ellipse", "ell2D", (0.15, 0.075), -math.pi/6, "ellipse 0.15, 0.075 (2D)"),
    ("drop2D-fine", "rectangle", "rect2D", (0.15, 0.06), math.pi/6, "rectangle, 80 x 80"),
    ("drop2D-fine", "ellipse", "ell2D", (0.15, 0.075), -math.pi/6, "ellipse, 80 x 80"),
    ("drop2D-steep", "rectangle", "rect2D", (0.15, 0.06), math.pi/3, "rectangle from 60 deg"),
    ("drop2D-steep", "ellipse", "ell2D", (0.15, 0.075), -4*math.pi/9, "ellipse from -80 deg"),
    ("drop3D", "ellipsoid", "ell3D", (0.15, 0.1, 0.09), None, "ellipsoid 0.15, 0.1, 0.09"),
    ("drop3D", "box", "box3D", (0.3, 0.2, 0.12), None, "triSurface box 0.3 x 0.2 x 0.12"),
    ("ellipsoid10", "ellipsoid", "ell3D", (0.15, 0.1, 0.09), None, "ellipsoid alone, to t = 10"),
    ("stl", "box", "box3D", (0.3, 0.2, 0.12), None, "stlSettling box (alone)"),
    ("stl-L2", "box", "box3D", (0.3, 0.2, 0.12), None, "stlSettling box, level 2"),
]

results = []
hist = {}
for scene, name, kind, dims, th0, label in restBodies:
    case = os.path.join(runs, scene)
    path = os.path.join(case, "postProcessing", "fbmBodies", "0", name + ".dat")
    if not os.path.exists(path):
        continue
    d = rows(path)
    t, y = d["Time"], d["y"]
    U = np.sqrt(d["Ux"]**2 + d["Uy"]**2 + d["Uz"]**2)
    w = np.sqrt(d["wx"]**2 + d["wy"]**2 + d["wz"]**2)
    face = ""
    longTilt = float("nan")
    if kind in ("rect2D", "ell2D"):
        th = th0 + d["angle"]
        a, b = dims
        if kind == "rect2D":
            low = a*np.abs(np.sin(th)) + b*np.abs(np.cos(th))
            R = math.hypot(a, b)
        else:
            low = np.hypot(a*np.sin(th), b*np.cos(th))
            R = a
        # long axis from the floor, wrapped to (-90, 90] degrees
        tilt = np.degrees(np.arctan(np.tan(th)))
        face = "long side" if abs(tilt[-1]) < 45 else "short side"
        restY = b
        ang = tilt
    else:
        Rs = [rot(q) for q in zip(d["qw"], d["qx"], d["qy"], d["qz"])]
        if kind == "ell3D":
            e = np.array(dims)
            low = np.array([math.sqrt(sum((e[k]*Rm[1][k])**2 for k in range(3))) for Rm in Rs])
            R = max(dims)
            # shortest axis (body z) from the vertical
            ang = np.degrees(np.arccos(np.minimum(1, [abs(Rm[1][2]) for Rm in Rs])))
            longTilt = math.degrees(math.asin(min(1, abs(Rs[-1][1][0]))))
            kUp = int(np.argmax([abs(Rs[-1][1][k]) for k in range(3)]))
            face = "axes " + ", ".join("%g" % dims[k] for k in range(3) if k != kUp) + " level"
            restY = dims[2]
        else:
            L = np.array(dims)
            low = np.array([sum(0.5*L[k]*abs(Rm[1][k]) for k in range(3)) for Rm in Rs])
            R = 0.5*math.sqrt(sum(x*x for x in dims))
            ang = np.degrees(np.arccos(np.minimum(1, [max(abs(Rm[1][k]) for k in range(3)) for Rm in Rs])))
            kUp = int(np.argmax([abs(Rs[-1][1][k]) for k in range(3)]))
            face = " x ".join("%g" % dims[k] for k in range(3) if k != kUp)
            longTilt = math.degrees(math.asin(min(1, abs(Rs[-1][1][0]))))
            restY = 0.5*dims[2]
        tilt = ang
    gap = y - low
    speed = U + w*R
    # The rest gap of the wall law (singhRepulsion, range rho_w 0.05, eps_W
    # 5e-5, applied as to a round body of the bounding radius R at that
    # gap: F = D' (s + rho_w - D')^2/eps_W, D' = 2 (R + gap), s = 2 R;
    # times the mesh depth 0.1 in 2D) against the submerged weight
    # (rho_s - rho_f) V g with rho_s 2, rho_f 1
    if kind == "rect2D":
        V = 4*dims[0]*dims[1]*0.1
    elif kind == "ell2D":
        V = math.pi*dims[0]*dims[1]*0.1
    elif kind == "ell3D":
        V = 4/3*math.pi*dims[0]*dims[1]*dims[2]
    else:
        V = dims[0]*dims[1]*dims[2]
    depth = 0.1 if kind in ("rect2D", "ell2D") else 1.0
    lo, hi = 0.0, rangeWall/2
    for _ in range(100):
        gm = 0.5*(lo + hi)
        F = depth*2*(R + gm)*(rangeWall - 2*gm)**2/5e-5
        lo, hi = (gm, hi) if F > (2 - 1)*V*g else (lo, gm)
    gapLaw = 0.5*(lo + hi)
    land, settle = settleTimes(t, speed, gap)
    summ = rows(os.path.join(case, "postProcessing", "fbmBodies", "0", "summary.dat"))
    wallSub = summ["minWallGap"][summ["minWallGap"] < 1e14].min()
    results.append({
        "scene": scene, "body": name, "cells": cells(case),
        "t_end": t[-1], "t_land": land, "t_settle": settle,
        "y_final": y[-1], "y_flat": restY, "gap_final": gap[-1], "gap_law": gapLaw, "gap_min": gap.min(), "wallGap_min_scene": wallSub,
        "tilt_deg": abs(tilt[-1]), "longAxisTilt_deg": longTilt, "face_down": face,
        "U_final": U[-1], "omegaR_final": w[-1]*R, "speed_max": speed.max(),
        "cpu_s": cpu(case)})
    hist[(scene, name)] = (label, t, y, tilt, U, w*R, gap)

cols = ["scene", "body", "cells", "t_end", "t_land", "t_settle", "y_final", "y_flat",
        "gap_final", "gap_law", "gap_min", "wallGap_min_scene", "tilt_deg", "longAxisTilt_deg", "face_down",
        "U_final", "omegaR_final", "speed_max", "cpu_s"]
with open("results.csv", "w", newline="") as f:
    wr = csv.writer(f)
    wr.writerow(cols)
    for r in results:
        wr.writerow([r[c] if isinstance(r[c], str) else "%.6g" % r[c] for c in cols])

# ---- Collisions -------------------------------------------------------------
a, b, depth, rho = 0.1, 0.05, 0.1, 1.0
m = rho*math.pi*a*b*depth
I = m*(a*a + b*b)/4
O = np.array([0.0, 0.0])
coll = []
chist = {}
for scene in ("headOn", "oblique", "headOn-rhoF1e-6", "headOn-rhoF4e-6"):
    case = os.path.join(runs, scene)
    base = os.path.join(case, "postProcessing", "fbmBodies", "0")
    if not os.path.exists(os.path.join(base, "e0.dat")):
        continue
    ds = [rows(os.path.join(base, n + ".dat")) for n in ("e0", "e1")]
    t = ds[0]["Time"]
    dt = np.diff(t, prepend=0.0)
    P = sum(m*np.array([d["Ux"], d["Uy"]]) for d in ds)
    L = sum(m*((d["x"] - O[0])*d["Uy"] - (d["y"] - O[1])*d["Ux"]) + I*d["wz"] for d in ds)
    E = sum(0.5*m*(d["Ux"]**2 + d["Uy"]**2) + 0.5*I*d["wz"]**2 for d in ds)
    # the fluid's impulse: the force of each step acts over the next one
    # (explicit coupling: bodies move with the last step's force)
    Fimp = sum(np.array([np.sum(d["Fx"][:-1]*dt[1:]), np.sum(d["Fy"][:-1]*dt[1:])]) for d in ds)
    # and its moment about O with the lever arm at the middle of that step
    Limp = 0.0
    for d in ds:
        xm = 0.5*(d["x"][:-1] + d["x"][1:]) - O[0]
        ym = 0.5*(d["y"][:-1] + d["y"][1:]) - O[1]
        Limp += np.sum((xm*d["Fy"][:-1] - ym*d["Fx"][:-1] + d["Tz"][:-1])*dt[1:])
    # the fluid's work, with the velocities at the middle of the step
    W = 0.0
    for d in ds:
        mid = {k: 0.5*(d[k][:-1] + d[k][1:]) for k in ("Ux", "Uy", "wz")}
        W += np.sum((d["Fx"][:-1]*mid["Ux"] + d["Fy"][:-1]*mid["Uy"] + d["Tz"][:-1]*mid["wz"])*dt[1:])
    summ = rows(os.path.join(base, "summary.dat"))
    u = 1.0
    Lref = m*u*1.0      # m u times the box size
    coll.append({
        "run": scene, "solver": "fbmFoam", "bodies": "ellipses 0.1, 0.05",
        "rhoFluid": float(re.search(r"^rhoFluid\s+([^;]+);",
                                    open(os.path.join(case, "constant", "fbmProperties")).read(), re.M).group(1)),
        "Px_before": P[0][0], "Py_before": P[1][0], "Px_after": P[0][-1], "Py_after": P[1][-1],
        "dP_rel": math.hypot(P[0][-1] - P[0][0], P[1][-1] - P[1][0])/(m*u),
        "fluidImpulse_rel": math.hypot(*Fimp)/(m*u),
        "dPcontact_rel": math.hypot(P[0][-1] - P[0][0] - Fimp[0], P[1][-1] - P[1][0] - Fimp[1])/(m*u),
        "L_before": L[0], "L_after": L[-1],
        "dL_rel": abs(L[-1] - L[0])/Lref, "fluidAngImpulse_rel": abs(Limp)/Lref,
        "dLcontact_rel": abs(L[-1] - L[0] - Limp)/Lref,
        "E_ratio": E[-1]/E[0], "E_ratio_contact": (E[-1] - W)/E[0],
        "minPairGap": summ["minPairGap"].min(),
        "omega0_after": ds[0]["wz"][-1], "omega1_after": ds[1]["wz"][-1],
        "cpu_s": cpu(case)})
    # cumulative fluid impulse and angular impulse at each output time
    J = np.zeros((2, len(t)))
    K = np.zeros(len(t))
    for d in ds:
        J[0][1:] += np.cumsum(d["Fx"][:-1]*dt[1:])
        J[1][1:] += np.cumsum(d["Fy"][:-1]*dt[1:])
        xm = 0.5*(d["x"][:-1] + d["x"][1:]) - O[0]
        ym = 0.5*(d["y"][:-1] + d["y"][1:]) - O[1]
        K[1:] += np.cumsum((xm*d["Fy"][:-1] - ym*d["Fx"][:-1] + d["Tz"][:-1])*dt[1:])
    dP = np.hypot(P[0] - P[0][0], P[1] - P[1][0])/(m*u)
    dPc = np.hypot(P[0] - P[0][0] - J[0], P[1] - P[1][0] - J[1])/(m*u)
    chist[scene] = (t, dP, dPc, np.abs(L - L[0])/Lref, np.abs(L - L[0] - K)/Lref,
                    E/E[0], [d["wz"] for d in ds])

for dim in ("2D", "3D"):
    log = os.path.join(runs, "dem", "log." + dim)
    if not os.path.exists(log):
        continue
    mt = re.search(r"head-on ellips\w+: .*\|dP\| ([^,]+), \|dL\| ([^,]+), "
                   r"energy after/before ([^,]+), omega \(([^)]*)\) \(([^)]*)\)",
                   open(log).read())
    gapm = re.search(r"head-on ellips\w+: .*smallest gap ([^,]+),", open(log).read())
    if dim == "2D":
        mm, lab, Rb = m, "ellipses 0.1, 0.05", 0.1
    else:
        mm, lab, Rb = 4/3*math.pi*0.1*0.06*0.04, "ellipsoids 0.1, 0.06, 0.04", 0.1
    nan = float("nan")
    coll.append({
        "run": "dem-" + dim, "solver": "Test-convexDistance", "bodies": lab, "rhoFluid": 0.0,
        "Px_before": 0.0, "Py_before": 0.0, "Px_after": nan, "Py_after": nan,
        "dP_rel": float(mt.group(1))/mm, "fluidImpulse_rel": 0.0,
        "dPcontact_rel": float(mt.group(1))/mm, "dLcontact_rel": float(mt.group(2))/mm,
        "L_before": nan, "L_after": nan,
        "dL_rel": float(mt.group(2))/mm, "fluidAngImpulse_rel": 0.0,
        "E_ratio": float(mt.group(3)), "E_ratio_contact": float(mt.group(3)),
        "minPairGap": float(gapm.group(1)),
        "omega0_after": float(mt.group(4).split()[-1]), "omega1_after": float(mt.group(5).split()[-1]),
        "cpu_s": nan})

ccols = ["run", "solver", "bodies", "rhoFluid", "Px_before", "Py_before", "Px_after", "Py_after",
         "dP_rel", "fluidImpulse_rel", "dPcontact_rel", "L_before", "L_after", "dL_rel",
         "fluidAngImpulse_rel", "dLcontact_rel", "E_ratio", "E_ratio_contact", "minPairGap", "omega0_after",
         "omega1_after", "cpu_s"]
with open("collisions.csv", "w", newline="") as f:
    wr = csv.writer(f)
    wr.writerow(ccols)
    for r in coll:
        wr.writerow([r[c] if isinstance(r[c], str) else "%.6g" % r[c] for c in ccols])

# ---- table.md -----------------------------------------------------------------
def fmt(x, spec):
    return "" if isinstance(x, float) and math.isnan(x) else spec.format(x)


with open("table.md", "w") as f:
    f.write("| scene | body | cells | t end | lands at t | settled from t | tilt from stable [deg] | lies on | gap at end | gap of the law at rest | smallest gap | abs(U) at end | abs(omega) R at end | CPU s |\n")
    f.write("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n")
    for r in results:
        f.write("| %s | %s | %s | %g | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n" % (
            r["scene"], r["body"], "{:,}".format(r["cells"]), r["t_end"],
            fmt(r["t_land"], "{:.2f}"), fmt(r["t_settle"], "{:.2f}"),
            fmt(r["tilt_deg"], "{:.2g}"), r["face_down"],
            fmt(r["gap_final"], "{:.5f}"), fmt(r["gap_law"], "{:.5f}"), fmt(r["gap_min"], "{:.4f}"),
            fmt(r["U_final"], "{:.1e}"), fmt(r["omegaR_final"], "{:.1e}"),
            fmt(r["cpu_s"], "{:.0f}")))
    f.write("\n| run | solver | bodies | rho_f / rho_s | P before / (m u) | P after / (m u) | abs(dP) / (m u) | fluid's impulse | abs(dP - fluid's) | L_O before / (m u l) | L_O after / (m u l) | abs(dL_O - fluid's) | E after / before | the same less the fluid's work | smallest pair gap [m] |\n")
    f.write("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n")
    for r in coll:
        fb = r["solver"] == "fbmFoam"
        pb = "(%.2g, %.2g)" % (r["Px_before"]/m, r["Py_before"]/m) if fb else "(0, 0)"
        pa = "(%.2g, %.2g)" % (r["Px_after"]/m, r["Py_after"]/m) if fb else ""
        f.write("| %s | %s | %s | %s | %s | %s | %s | %s | %.1e | %s | %s | %.1e | %.5f | %s | %.4f |\n" % (
            r["run"], r["solver"], r["bodies"],
            "%g" % r["rhoFluid"] if fb else "no fluid", pb, pa,
            "%.1e" % r["dP_rel"] if fb else "",
            "%.1e" % r["fluidImpulse_rel"] if fb else "none",
            r["dPcontact_rel"],
            "%.7f" % (r["L_before"]/m) if fb else "",
            "%.7f" % (r["L_after"]/m) if fb else "",
            r["dLcontact_rel"], r["E_ratio"],
            "%.5f" % r["E_ratio_contact"] if fb else "", r["minPairGap"]))

# ---- settling.png -----------------------------------------------------------
if hist:
    fig, ax = plt.subplots(3, 2, figsize=(11, 9), sharex="col")
    colour = {"rectangle": "C0", "ellipse": "C1", "ellipsoid": "C2", "box": "C3"}
    style = {"drop2D-fine": "--", "stl-L2": "--", "drop2D-steep": "-.", "ellipsoid10": ":"}
    for (scene, name), (label, t, y, tilt, U, wR, gap) in hist.items():
        col = 0 if scene.startswith("drop2D") else 1
        c = "C4" if scene.startswith("stl") else colour[name]
        ls = style.get(scene, "-")
        ax[0][col].plot(t, y, ls, color=c, label=label)
        ax[1][col].plot(t, tilt, ls, color=c)
        ax[2][col].semilogy(t, np.maximum(U + wR, 1e-9), ls, color=c)
    ax[0][0].set_title("2D (fbmFoam, 40 x 40)")
    ax[0][1].set_title("3D (fbmFoam, 20^3)")
    for col in (0, 1):
        ax[0][col].set_ylabel("centre height y [m]")
        ax[0][col].legend(fontsize=8)
        ax[2][col].set_ylabel("abs(U) + abs(omega) R [m/s]")
        ax[2][col].set_xlabel("t [s]")
        ax[2][col].set_ylim(1e-6, 2)
        for a_ in ax[:, col]:
            a_.grid(alpha=0.3)
    ax[1][0].set_ylabel("long axis from the floor [deg]")
    ax[1][1].set_ylabel("tilt from the stable axis [deg]\n(box: nearest axis; ellipsoid: shortest axis)")
    fig.tight_layout()
    fig.savefig("settling.png", dpi=110)

# ---- collisions.png ---------------------------------------------------------
if chist:
    fig, ax = plt.subplots(2, 2, figsize=(11, 7), sharex=True)
    for scene, (t, dP, dPc, dL, dLc, En, ws) in chist.items():
        if scene not in ("headOn", "oblique"):
            continue
        c = "C0" if scene == "headOn" else "C1"
        ax[0][0].semilogy(t, np.maximum(dP, 1e-17), color=c, label=scene + ": all")
        ax[0][0].semilogy(t, np.maximum(dPc, 1e-17), ":", color=c, label=scene + ": less the fluid's impulse")
        ax[0][1].semilogy(t, np.maximum(dL, 1e-17), color=c, label=scene + ": all")
        ax[0][1].semilogy(t, np.maximum(dLc, 1e-17), ":", color=c, label=scene + ": less the fluid's")
        ax[1][0].plot(t, En, color=c, label=scene)
        ax[1][1].plot(t, ws[0], color=c, label=scene + ": e0")
        ax[1][1].plot(t, ws[1], "--", color=c, label=scene + ": e1")
    ax[0][0].set_ylabel("abs(P - P(0)) / (m u)")
    ax[0][1].set_ylabel("abs(L_O - L_O(0)) / (m u l)\nO = (0, 0), l = 1 m")
    ax[1][0].set_ylabel("kinetic energy / start")
    ax[1][1].set_ylabel("omega [rad/s]")
    for a_ in ax.flat:
        a_.grid(alpha=0.3)
        a_.legend(fontsize=8)
    for a_ in ax[1]:
        a_.set_xlabel("t [s]")
    fig.tight_layout()
    fig.savefig("collisions.png", dpi=110)

for r in results:
    print("%-7s %-10s tilt %.3g deg, |U| %.2g, |omega|R %.2g, gap %.4f, land %.2f, settle %s, cpu %.0f"
          % (r["scene"], r["body"], r["tilt_deg"], r["U_final"], r["omegaR_final"],
             r["gap_final"], r["t_land"], fmt(r["t_settle"], "{:.2f}"), r["cpu_s"]))
for r in coll:
    print("%-8s dP %.2e (fluid %.2e, rest %.2e), dL %.2e (fluid %.2e, rest %.2e), E %.5f, gap %.4f"
          % (r["run"], r["dP_rel"], r["fluidImpulse_rel"], r["dPcontact_rel"], r["dL_rel"],
             r["fluidAngImpulse_rel"], r["dLcontact_rel"], r["E_ratio"], r["minPairGap"]))
