#!/usr/bin/python3
"""One row of results.csv from a run of the 3D moving-body check (Allrun).

Usage: analyse.py CASE RUN R/h KIND V DT PREDICTOR MAXCO WALL_S
       analyse.py -header

Drag Fy: the y force on the sphere (postProcessing/fbmBodies/0/sphere.dat).
  bodyFrame: Fy at the end; Fy_min, Fy_max and the rms over t > 0.3 (steady:
             status ok when max - min < 1e-3 Fy, else unsteady).
  moving:    the mean over 0.2 < t <= 0.4 (an even number of steps: the
             drag alternates from step to step at a body Courant number
             0.5); Fy_rms_pct the rms of the drag about that mean in % of
             it (the grid-crossing noise, as ../movingBody computes it);
             Fy_drift_pct the mean of the window's second half against its
             first half (start-up or the box's ends).
  status diverged: |Fy| > 3 (ten times the drag) at some step; t_diverged
  the first such time.
dt: the moving run's fixed step, the body frame's last step; Co_body
V dt/h, visc nu dt/h^2 (nu 0.1); cpu_s the solver's last ExecutionTime.
"""
import math
import re
import sys

cols = ("run,RH,case,predictor,dt,Co_body,visc,maxCo,cells,status,t_diverged,"
        "Fy,Fy_min,Fy_max,Fy_rms_pct,Fy_drift_pct,wall_s,cpu_s")
if sys.argv[1] == "-header":
    print(cols)
    sys.exit(0)

case, run, RH, kind, V, dt, predictor, maxCo, wall = sys.argv[1:]
RH, V = float(RH), float(V)
h = 0.05/RH
nu = 0.1

log = open(case + "/log.fbmFoam").read()
cells = int(re.search(r"nCells:\s*(\d+)", open(case + "/log.blockMesh").read()).group(1))
cpu = re.findall(r"^ExecutionTime = ([0-9.eE+-]+) s", log, re.M)
cpu = float(cpu[-1]) if cpu else float("nan")
if kind == "bodyFrame":
    dts = re.findall(r"^deltaT = ([0-9.eE+-]+)", log, re.M)
    dt = float(dts[-1]) if dts else float(dt)
else:
    dt = float(dt)

t, F = [], []
for line in open(case + "/postProcessing/fbmBodies/0/sphere.dat"):
    if line.startswith("#"):
        continue
    w = line.split()
    t.append(float(w[0]))
    F.append(float(w[2]))

status, tDiv = "ok", ""
bad = [ti for ti, f in zip(t, F) if not abs(f) < 3]
Fy = Fmin = Fmax = rms = drift = ""
if kind == "moving":
    maxCo = ""
if bad:
    status, tDiv = "diverged", "%g" % bad[0]
elif kind == "bodyFrame":
    w = [f for ti, f in zip(t, F) if ti > 0.3]
    m = sum(w)/len(w)
    Fy, Fmin, Fmax = "%.5f" % F[-1], "%.5f" % min(w), "%.5f" % max(w)
    rms = "%.3f" % (100*math.sqrt(sum((f - m)**2 for f in w)/len(w))/abs(m))
    if max(w) - min(w) > 1e-3*abs(F[-1]):
        status = "unsteady"
else:
    w = [f for ti, f in zip(t, F) if 0.2 + 1e-9 < ti < 0.4 + 1e-9]
    if len(w) % 2:
        w = w[1:]
    n = len(w)
    m = sum(w)/n
    Fy, Fmin, Fmax = "%.5f" % m, "%.5f" % min(w), "%.5f" % max(w)
    rms = "%.3f" % (100*math.sqrt(sum((f - m)**2 for f in w)/n)/m)
    half = n//2 - (n//2) % 2
    drift = "%.3f" % (100*(sum(w[half:])/(n - half) - sum(w[:half])/half)/m)

print("%s,%g,%s,%s,%.6g,%.3f,%.3f,%s,%d,%s,%s,%s,%s,%s,%s,%s,%s,%.1f"
      % (run, RH, kind, predictor, dt, V*dt/h, nu*dt/h**2, maxCo, cells,
         status, tDiv, Fy, Fmin, Fmax, rms, drift, wall, cpu))
