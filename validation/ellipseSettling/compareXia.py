#!/usr/bin/python3
"""fbmFoam against the settling ellipse of Xia et al. (2009), as digitized.

Xia, Connington, Rapaka, Yue, Feng & Chen (2009, J. Fluid Mech. 625,
249-272) validate their lattice Boltzmann method on an ellipse of major
axis A = 0.1 cm and aspect ratio 2, density ratio 1.1, settling in a
channel L = 4 A wide from rest at 45 degrees on the centre line. The body
of the paper could not be read here; the reference is the digitized curves
of that case in the test suite of the FEN solver (F. De Vita,
https://github.com/fradevita/FEN, commit ed2afa44c5bf, folder
test/small_test/fsi/falling_ellipse/, files xref.txt, thetaref.txt and
vref.txt, labelled "Xia et al. (2009)"; the set-up there: A = 0.1 cm,
B = A/2, L = 4 A, rho_s/rho_f = 1.1, nu = 0.01 cm^2/s, Re = V A/nu = 12.5
and Fr = V/sqrt(g A) = 0.126 as scales, i.e. g = 984 cm/s^2 from the
rounded Fr, about 980). Those files are not in this repository (third-party
data); put them in runs/xiaReference/ (or point XIA_REF_DIR at them), for
example

    git clone https://github.com/fradevita/FEN
    git -C FEN show ed2afa44c5bf:test/small_test/fsi/falling_ellipse/xref.txt

and the same for thetaref.txt and vref.txt. Without them this script says
so and writes nothing.

Read as: xref.txt the lateral position x/A (channel centre at 2) and
thetaref.txt the angle of the major axis theta/pi (0.25 at the release),
both against the height y/A, the release at y/A = 24 (the first points:
x/A = 2.00, theta/pi = 0.25 at y/A = 23.98), so the fallen distance is
(24 - y)/A; vref.txt the vertical velocity [cm/s] against t [s].

The fbmFoam case (tutorials/fbmFoam/ellipseSettling) is this one scaled by
2: a = 0.1 = A/2, L = 0.8 = 4 A, g = 980. With g and the density ratio
fixed, the Galileo number sqrt(g (rho_s/rho_f - 1) A^3)/nu matches when
nu = 0.01 * 2^1.5 = 0.028284 (runs fbm-nu0.028284-L*); lengths then scale
by 2, velocities and times by sqrt(2). Everything here is in Xia's units
(A = 0.1 cm): fbmFoam's x - L/2 and fallen distance divided by A = 0.2, its
velocity and time divided by sqrt(2).

Compared (xia.csv, one row a quantity: the reference, and for each run
its value and its error, in % of the reference's value or, for angles and
positions, in the quantity's own unit):
- U_t: the mean settling velocity over 0.5 <= t <= 0.97 s (the reference
  points after the start-up, to the last one);
- the same over 0.5 <= t <= 0.7 s (what the -short runs reach);
- U at the reference's first point (t = 0.005 s, the start from rest),
  and the largest and the mean difference at the others, in % of the
  reference's U_t;
- the first turn: the fallen distance where theta first crosses 0, the
  first overshoot of theta (its extremum and where), the largest lateral
  drift |x - L/2| (and where);
- the later swings of theta: the extrema between crossings of 0 (the
  reference's from its points, so limited by their spacing), up to the
  fallen distance the fbmFoam channel allows (the analysis stops 3 A above
  the bottom wall, as plotResults.py), and their mean spacing in fallen
  distance (half the wavelength of the swing);
- the curves: the rms and largest difference of theta [deg] and of
  (x - L/2)/A at the reference's points within that distance.
Writes xia.csv and xia.png.
"""
import csv
import glob
import math
import os
import sys

import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

scale = 2.0                 # fbmFoam lengths / Xia's
A = 0.2                     # fbmFoam's major axis [cm]
xMid, y0, yCut = 0.4, 3.4, 0.6
theta0 = 45.0
uWindow = (0.5, 0.97)       # s, Xia's time: the settled part of vref.txt
uWindow2 = (0.5, 0.7)       # the part of it the -short runs reach

refDir = os.environ.get("XIA_REF_DIR", "runs/xiaReference")
files = [os.path.join(refDir, f + ".txt") for f in ("xref", "thetaref", "vref")]
if not all(os.path.exists(f) for f in files):
    print("compareXia.py: the digitized reference (xref.txt, thetaref.txt, "
          "vref.txt) is not in %s; see this script's header. Nothing "
          "written." % refDir)
    sys.exit(0)
xr, thr, vr = (np.loadtxt(f) for f in files)
# Fallen distance [A], sorted along the fall; (x - L/2)/A; theta [deg];
# a point digitized twice (thetaref.txt has one) counted once
refX = (24 - xr[::-1, 0], xr[::-1, 1] - 2.0)
d, i = np.unique(24 - thr[:, 0], return_index=True)
refTh = (d, 180*thr[i, 1])
refV = (vr[:, 0], -vr[:, 1])

# Runs that reached their endTime only (a run that stopped, as one whose
# coupling ran away, is reported by plotResults.py)
runs = sorted(os.path.basename(c) for c in glob.glob("runs/fbm-nu0.028284-L*")
              if os.path.exists(os.path.join(c, "runDone"))
              and "\nEnd" in open(os.path.join(c, "log.fbmFoam")).read())


def history(run):
    dat = np.loadtxt(os.path.join("runs", run,
                                  "postProcessing/fbmBodies/0/ellipse.dat"))
    t, x, y, uy = dat[:, 0], dat[:, 7], dat[:, 8], dat[:, 11]
    theta = theta0 + np.degrees(dat[:, -1])
    below = np.nonzero(y < yCut)[0]
    n = below[0] if len(below) else len(t)
    t, x, y, uy, theta = t[:n], x[:n], y[:n], uy[:n], theta[:n]
    s = math.sqrt(scale)
    return dict(t=t/s, d=(y0 - y)/A, x=(x - xMid)/A, U=-uy/s, theta=theta)


def crossing(d, th):
    """Where theta first crosses 0 (linear interpolation)."""
    i = np.nonzero(th <= 0)[0]
    if not len(i) or i[0] == 0:
        return float("nan")
    i = i[0]
    return d[i - 1] + th[i - 1]/(th[i - 1] - th[i])*(d[i] - d[i - 1])


def swings(d, th, dMax):
    """The extrema of theta between its crossings of 0, after the first
    crossing, up to dMax: [(d, theta)], the last one only if theta has
    crossed 0 again after it."""
    k = d <= dMax
    d, th = d[k], th[k]
    cr = np.nonzero(np.sign(th[1:]) != np.sign(th[:-1]))[0] + 1
    out = []
    for i, j in zip(cr[:-1], cr[1:]):
        m = i + np.argmax(np.abs(th[i:j]))
        out.append((d[m], th[m]))
    return out


def drift(d, x, dMax):
    """The largest |x - L/2| within the first turn (d <= dMax)."""
    k = np.nonzero(d <= dMax)[0]
    m = k[np.argmax(np.abs(x[k]))]
    return d[m], x[m]


rows = {}                   # quantity: its row of xia.csv


def add(run, quantity, unit, ours, ref, err, errUnit):
    """A quantity of a run: the columns NAME and NAME_error of the row of
    the quantity, NAME the run's name after 'fbm-nu0.028284-' without
    '-' (L2, L3short)"""
    name = run.split("-", 2)[2].replace("-", "")
    r = rows.setdefault(quantity, dict(quantity=quantity, unit=unit,
                                       reference="" if ref is None
                                       else "%.4g" % ref,
                                       error_unit=errUnit))
    r[name] = "%.4g" % ours
    r[name + "_error"] = "" if err is None else "%.3g" % err


def pct(a, b):
    return 100*(a - b)/b


refDcross = crossing(*refTh)
refSw = swings(refTh[0], refTh[1], 99)
# The reference's first turn ends at its first overshoot
refTurnEnd = refSw[0][0] if refSw else 4.0
refDrift = drift(refX[0], refX[1], refTurnEnd + 1)
kU = (refV[0] >= uWindow[0]) & (refV[0] <= uWindow[1])
refUt = np.mean(refV[1][kU])
kU2 = (refV[0] >= uWindow2[0]) & (refV[0] <= uWindow2[1])
refUt2 = np.mean(refV[1][kU2])

hists = {}
for run in runs:
    h = history(run)
    hists[run] = h
    dMax = h["d"][-1]
    # U_t and U(t), where this run reaches
    tU = refV[0][kU]
    if h["t"][-1] >= uWindow[1]:
        k = (h["t"] >= uWindow[0]) & (h["t"] <= uWindow[1])
        ut = np.mean(h["U"][k])
        add(run, "U_t (mean over t = 0.5-0.97 s)", "cm/s", ut, refUt,
            pct(ut, refUt), "%")
    if h["t"][-1] >= uWindow2[1]:
        k = (h["t"] >= uWindow2[0]) & (h["t"] <= uWindow2[1])
        ut = np.mean(h["U"][k])
        add(run, "U mean over t = 0.5-0.7 s", "cm/s", ut, refUt2,
            pct(ut, refUt2), "%")
    # The first point (t = 0.005 s) apart: the start from rest, where a
    # digitized point is least sure of its time
    u0 = np.interp(refV[0][0], h["t"], h["U"])
    add(run, "U at the first point, t = %.4f s" % refV[0][0], "cm/s", u0,
        refV[1][0], u0 - refV[1][0], "cm/s")
    u1 = np.interp(refV[0][1], h["t"], h["U"])
    add(run, "U at the second point, t = %.4f s" % refV[0][1], "cm/s", u1,
        refV[1][1], u1 - refV[1][1], "cm/s")
    kt = (refV[0] <= h["t"][-1]) & (refV[0] > refV[0][0])
    dU = np.interp(refV[0][kt], h["t"], h["U"]) - refV[1][kt]
    add(run, "U(t), the other points it reaches: time of the largest abs. "
        "difference", "s", refV[0][kt][np.argmax(np.abs(dU))], None, None,
        "")
    add(run, "U(t), the other points it reaches: largest abs. difference",
        "cm/s", np.max(np.abs(dU)), None,
        100*np.max(np.abs(dU))/refUt, "% of reference U_t")
    add(run, "U(t), the same points: mean difference", "cm/s",
        np.mean(dU), None,
        100*np.mean(dU)/refUt, "% of reference U_t")
    # The first turn
    dc = crossing(h["d"], h["theta"])
    add(run, "fallen distance at the first crossing of theta = 0", "A", dc,
        refDcross, dc - refDcross, "A")
    sw = swings(h["d"], h["theta"], dMax)
    turnEnd = sw[0][0] if sw else dMax
    dd, xx = drift(h["d"], h["x"], turnEnd + 1)
    add(run, "largest drift from the centre line in the first turn", "A", abs(xx),
        abs(refDrift[1]), pct(abs(xx), abs(refDrift[1])), "%")
    add(run, "fallen distance at the largest drift", "A", dd, refDrift[0],
        dd - refDrift[0], "A")
    # The swings of theta, as far as both go
    pairs = list(zip(sw, [p for p in refSw if p[0] <= dMax]))
    for n, (s, r) in enumerate(pairs):
        add(run, "theta extremum %d" % (n + 1), "deg", s[1], r[1],
            s[1] - r[1], "deg")
        add(run, "fallen distance at theta extremum %d" % (n + 1), "A", s[0],
            r[0],
            s[0] - r[0], "A")
    if len(pairs) >= 2:
        sp = (pairs[-1][0][0] - pairs[0][0][0])/(len(pairs) - 1)
        rp = (pairs[-1][1][0] - pairs[0][1][0])/(len(pairs) - 1)
        add(run, "mean spacing of extrema 1-%d (half a swing)" % len(pairs),
            "A", sp, rp, pct(sp, rp), "%")
    # The curves at the reference's points
    for name, (rd, rv), key, unit in (("theta", refTh, "theta", "deg"),
                                      ("(x - L/2)/A", refX, "x", "A")):
        k = rd <= dMax
        diff = np.interp(rd[k], h["d"], h[key]) - rv[k]
        add(run, "%s: rms difference at the reference's points it reaches"
            % name, unit,
            math.sqrt(np.mean(diff**2)), None, math.sqrt(np.mean(diff**2)),
            unit)
        add(run, "%s: largest abs. difference there" % name, unit,
            np.max(np.abs(diff)), None, np.max(np.abs(diff)), unit)
        add(run, "%s: fallen distance of the largest abs. difference" % name,
            "A", rd[k][np.argmax(np.abs(diff))], None, None, "")

names = [run.split("-", 2)[2].replace("-", "") for run in runs]
keys = ["quantity", "unit", "reference"]
for n in names:
    keys += [n, n + "_error"]
keys.append("error_unit")
with open("xia.csv", "w", newline="") as f:
    f.write("# fbmFoam (runs fbm-nu0.028284-NAME, in Xia's units) against "
            "Xia et al. (2009) as digitized in FEN (compareXia.py); "
            "NAME_error in error_unit\n")
    wr = csv.DictWriter(f, keys, restval="")
    wr.writeheader()
    wr.writerows(rows.values())
    # The reference alone: its scatter about 0 where the swing has died,
    # a measure of the digitization
    k = refTh[0] > 16
    wr.writerow(dict(quantity="reference only: largest abs. theta beyond "
                     "16 A of fall (the swing has died)", unit="deg",
                     reference="%.4g" % np.max(np.abs(refTh[1][k]))))
    k = refV[0] >= 0.3
    wr.writerow(dict(quantity="reference only: half the range of U over "
                     "t = 0.3-0.97 s, in % of its U_t", unit="%",
                     reference="%.3g" % (50*np.ptp(refV[1][k])/refUt)))
print(open("xia.csv").read())

fig, ax = plt.subplots(1, 3, figsize=(16, 4.8))
ax[0].plot(refX[0], refX[1], "ko", ms=4, mfc="none",
           label="Xia et al. 2009 (digitized, FEN)")
ax[1].plot(refTh[0], refTh[1], "ko", ms=4, mfc="none",
           label="Xia et al. 2009 (digitized, FEN)")
ax[2].plot(refV[0], refV[1], "ko", ms=4, mfc="none",
           label="Xia et al. 2009 (digitized, FEN)")
for run, h in hists.items():
    ax[0].plot(h["d"], h["x"], "-", lw=1.2, label=run)
    ax[1].plot(h["d"], h["theta"], "-", lw=1.2, label=run)
    ax[2].plot(h["t"], h["U"], "-", lw=1.2, label=run)
ax[0].set_xlabel("fallen distance [A]")
ax[0].set_ylabel("(x - L/2)/A")
ax[0].set_title("lateral position")
ax[1].axhline(0, color="k", lw=0.5)
ax[1].set_xlabel("fallen distance [A]")
ax[1].set_ylabel("angle of the major axis to the horizontal [deg]")
ax[1].set_title("orientation")
ax[2].set_xlabel("t [s] (Xia's size, A = 0.1 cm)")
ax[2].set_ylabel("settling velocity [cm/s]")
ax[2].set_title("settling velocity")
ax[2].set_xlim(0, 1.05)
for a_ in ax:
    a_.legend(fontsize=7)
fig.suptitle("Ellipse A/B = 2, rho_s/rho_f = 1.1, A/L = 0.25, nu = 0.01, "
             "A = 0.1 cm (Xia et al. 2009's validation case as set up and "
             "digitized in FEN); fbmFoam at twice the size, nu = 0.028284, "
             "shown in Xia's units", fontsize=8)
fig.tight_layout()
fig.savefig("xia.png", dpi=110)
