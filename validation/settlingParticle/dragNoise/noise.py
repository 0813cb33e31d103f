#!/usr/bin/python3
"""Drag noise of the settling disk runs of ./Allrun, and where it comes from.

Usage: noise.py RUNS_DIR OUT.csv

For each run in RUNS_DIR and each of its body files (particle.dat: the force
model momentumExchange; particle.volumeIntegral.dat: the compared
volumeIntegral), over the records where the disk's speed is at least 98 % of
its largest (terminal speed; for a disk moved at a prescribed constant
speed the records after 6 d of travel while it is at least d from the
bottom):
- noise_pct: the drag noise of validation/settlingParticle/plotResults.py,
  the rms of Fy about its centred running mean over 21 records, in % of the
  mean drag;
- peak_over_crossing: the frequency of the largest peak of that deviation's
  spectrum over the cell-crossing frequency U/h (U the largest speed, h the
  cell size); 1 and 2 are the first two harmonics of the grid crossing;
- steps_per_crossing: h/(U dt), dt the mean step there;
- crossing_avg_noise_pct: the same noise after the drag is averaged over
  one cell crossing (a running mean over steps_per_crossing records);
- velocity_noise_pct: the noise of the disk's vertical velocity, in % of it;
- phase_share: the share of the noise's variance that a function of the
  disk's place in its cell explains (least squares on harmonics 1-3 of the
  front pole's position in its cell, (y - R)/h modulo 1): near 1 where the
  noise is a function of that place, as a smooth variation is and as an
  impulse that lands where the step puts the disk is too (it does not tell
  them apart);
- Re_max: rho_s max|U| d/mu while the disk is at least d from the bottom,
  as validation/settlingParticle/plotResults.py takes it (empty for a disk
  moved at a prescribed speed);
- coupling: the run's coupling, or prescribed;
- cpu_s: the run's CPU time (ExecutionTime of log.fbmFoam).
"""

import math
import os
import re
import sys

import numpy as np

HALF = 10          # the running mean of plotResults.py: 2 HALF + 1 records
WIDTH = 2.0        # the channel's width; n = 12*2^(level - 1) cells across it
RADIUS = 0.125     # the disk's radius (the bottom wall at y = 0)


def level(run):
    text = open(os.path.join(run, "system", "caseParameters")).read()
    return int(re.search(r"^level\s+(\d+)\s*;", text, re.M).group(1))


def setting(run, path, key):
    text = open(os.path.join(run, path)).read()
    m = re.search(r"^\s*%s\s+([^;\s]+)\s*;" % key, text, re.M)
    return m.group(1) if m else ""


def coupling(run, prescribed):
    """The coupling of a run: semiImplicit, semiImplicit-newton, explicit,
    or prescribed (the disk moved at a prescribed speed)"""
    if prescribed:
        return "prescribed"
    name = setting(run, "constant/fbmProperties", "coupling")
    text = open(os.path.join(run, "constant", "fbmProperties")).read()
    if re.search(r"^\s*pressureSolve\s+newton\s*;", text, re.M):
        name += "-newton"
    return name


def deviation(f, half):
    """f less its centred running mean over 2 half + 1 records"""
    k = np.ones(2*half + 1)/(2*half + 1)
    return (f - np.convolve(f, k, mode="same"))[half:len(f) - half]


def analyse(path, h):
    d = np.loadtxt(path, comments="#")
    far = d[:, 8] - RADIUS >= 2*RADIUS
    t, Fy, Uy = d[:, 0], d[:, 2], d[:, 11]
    speed = np.hypot(d[:, 10], d[:, 11])
    uMax = speed.max()
    prescribed = speed.min() > (1 - 1e-6)*uMax
    if prescribed:
        # A prescribed constant speed: after 6 d of travel, while at least
        # d from the bottom
        idx = np.where((t*uMax >= 12*RADIUS) & far)[0]
    else:
        idx = np.where(speed >= 0.98*uMax)[0]
    seg = slice(idx[0], idx[-1] + 1)
    f, tt = Fy[seg], t[seg]
    if len(f) < 4*HALF + 1:
        return None
    dev = deviation(f, HALF)
    mean = np.abs(f).mean()
    dt = np.diff(tt).mean()
    spec = np.abs(np.fft.rfft(dev*np.hanning(len(dev))))
    freq = np.fft.rfftfreq(len(dev), dt)
    peak = freq[1:][np.argmax(spec[1:])]
    per = h/(uMax*dt)
    n = max(1, int(round(per)))
    avg = np.convolve(f, np.ones(n)/n, mode="valid")
    vdev = deviation(Uy[seg], HALF)
    # The part of the noise that is a function of the front pole's place in
    # its cell
    phase = 2*math.pi*(((d[seg, 8] - RADIUS)/h) % 1.0)[HALF:len(f) - HALF]
    A = np.column_stack([np.ones_like(phase)]
                        + [g(k*phase) for k in (1, 2, 3) for g in (np.cos, np.sin)])
    c, *_ = np.linalg.lstsq(A, dev, rcond=None)
    phaseShare = 1 - ((dev - A @ c)**2).sum()/((dev - dev.mean())**2).sum()
    return {
        "prescribed": prescribed,
        "far_speed_max": speed[far].max(),
        "U_max": uMax,
        "dt": dt,
        "records": len(f),
        "mean_drag": mean,
        "noise_pct": 100*math.sqrt((dev**2).mean())/mean,
        "peak_over_crossing": peak/(uMax/h),
        "steps_per_crossing": per,
        "crossing_avg_noise_pct":
            100*math.sqrt((deviation(avg, HALF)**2).mean())/mean,
        "velocity_noise_pct":
            100*math.sqrt((vdev**2).mean())/np.abs(Uy[seg]).mean(),
        "phase_share": phaseShare,
    }


def main(runsDir, out):
    rows = []
    for name in sorted(os.listdir(runsDir)):
        run = os.path.join(runsDir, name)
        files = os.path.join(run, "postProcessing", "fbmBodies", "0")
        if not os.path.isdir(files):
            print("noise.py: no body files in %s" % run, file=sys.stderr)
            return 1
        h = WIDTH/(12*2**(level(run) - 1))
        for fname, model in (("particle.dat", "momentumExchange"),
                             ("particle.volumeIntegral.dat", "volumeIntegral")):
            r = analyse(os.path.join(files, fname), h)
            if r is None:
                print("noise.py: too few records at terminal speed in %s"
                      % run, file=sys.stderr)
                return 1
            rhoS = float(setting(run, "system/caseParameters", "rhoParticle"))
            nu = float(setting(run, "system/caseParameters", "nu"))
            cpu = re.findall(r"ExecutionTime = ([0-9.]+) s",
                             open(os.path.join(run, "log.fbmFoam")).read())
            r.update(Re_max=(float("nan") if r["prescribed"]
                             else rhoS*r["far_speed_max"]*2*RADIUS/nu),
                     cpu_s=float(cpu[-1]) if cpu else float("nan"))
            r.update(run=name, model=model,
                     nu=setting(run, "system/caseParameters", "nu"),
                     maxCo=setting(run, "system/controlDict", "maxCo"),
                     forcing=setting(run, "constant/fbmProperties", "forcing"),
                     coupling=coupling(run, r["prescribed"]),
                     R_over_h=0.125/h)
            rows.append(r)
    cols = ["run", "model", "nu", "maxCo", "forcing", "coupling",
            "R_over_h", "U_max",
            "dt", "records", "mean_drag", "noise_pct", "peak_over_crossing",
            "steps_per_crossing", "crossing_avg_noise_pct",
            "velocity_noise_pct", "phase_share", "Re_max", "cpu_s"]
    fmt = {"U_max": "%.4g", "dt": "%.3g", "mean_drag": "%.4g",
           "noise_pct": "%.3g", "peak_over_crossing": "%.2f",
           "steps_per_crossing": "%.2f", "crossing_avg_noise_pct": "%.3g",
           "velocity_noise_pct": "%.2g", "phase_share": "%.2f",
           "R_over_h": "%g",
           "Re_max": "%.4g", "cpu_s": "%.1f"}
    with open(out, "w") as f:
        f.write(",".join(cols) + "\n")
        for r in rows:
            f.write(",".join("" if isinstance(r[c], float) and math.isnan(r[c])
                             else fmt.get(c, "%s") % r[c] for c in cols) + "\n")
    print(open(out).read())
    return 0


if __name__ == "__main__":
    if len(sys.argv) != 3:
        print(__doc__, file=sys.stderr)
        sys.exit(1)
    sys.exit(main(sys.argv[1], sys.argv[2]))
