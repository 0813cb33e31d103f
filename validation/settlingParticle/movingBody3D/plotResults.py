#!/usr/bin/python3
"""Table and chart of the 3D moving-body check (Allrun).

table.md: every row of results.csv, the moving sphere's drag against the
body frame's at its R/h. drag.png: left, the drag history of the moving
sphere over the body frame's drag (from runs/, when there); right, the
error of the mean drag against R/h.
"""
import csv
import os

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

rows = list(csv.DictReader(open("results.csv")))
ref = {r["RH"]: float(r["Fy"]) for r in rows
       if r["case"] == "bodyFrame" and r["status"] == "ok"
       and r["run"] == "bodyFrame-R%s" % r["RH"]}


def err(r):
    if r["case"] != "moving" or r["status"] != "ok" or r["RH"] not in ref:
        return None
    return 100*(float(r["Fy"])/ref[r["RH"]] - 1)


with open("table.md", "w") as f:
    f.write("Sphere d = 0.1 at V = 1.666 in a 0.4 x 1.2 x 0.4 box; the weight "
            "a free sphere would balance, (rho_s - rho_f) g 4/3 pi R^3 = "
            "%.5f\n\n" % (0.5*980*4/3*3.141592653589793*0.05**3))
    f.write("| run | R/h | cells | predictor | dt | Co_body | nu dt/h^2 | "
            "status | Fy | min..max | rms % | drift % | error vs body frame "
            "| wall s | CPU s |\n")
    f.write("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n")
    for r in rows:
        e = err(r)
        st = r["status"] + (" at t = " + r["t_diverged"] if r["t_diverged"] else "")
        f.write("| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s "
                "| %s | %s | %s |\n"
                % (r["run"], r["RH"], r["cells"], r["predictor"], r["dt"],
                   r["Co_body"], r["visc"], st, r["Fy"],
                   "%s..%s" % (r["Fy_min"], r["Fy_max"]) if r["Fy_min"] else "",
                   r["Fy_rms_pct"], r["Fy_drift_pct"],
                   "%+.2f %%" % e if e is not None else "",
                   r["wall_s"], r["cpu_s"]))
print(open("table.md").read())



def history(run, RH):
    dat = "runs/%s/postProcessing/fbmBodies/0/sphere.dat" % run
    if not os.path.exists(dat):
        return [], []
    t, F = [], []
    for line in open(dat):
        if not line.startswith("#"):
            w = line.split()
            t.append(float(w[0]))
            F.append(float(w[2])/ref[RH])
    return t, F


fig, (c, a, b) = plt.subplots(1, 3, figsize=(15, 4.5))
colours = {"3": "tab:blue", "4": "tab:orange", "6": "tab:green"}

# Left: the step-to-step drag of the extrapolated predictor at Co_body 0.5
for r in rows:
    if r["case"] == "moving" and r["RH"] in ref and r["run"] in (
            "moving-R%s-extrap" % r["RH"], "moving-R%s-lagged" % r["RH"]):
        t, F = history(r["run"], r["RH"])
        c.plot(t, F, "-" if r["predictor"] == "lagged" else "--",
               color=colours.get(r["RH"], "k"), lw=0.8,
               label="%s (%s)" % (r["run"], r["status"]))
c.set_xlim(0, 0.2)
c.set_ylim(-1, 3)
c.set_xlabel("t")
c.set_ylabel("drag Fy / body-frame drag (same R/h)")
c.set_title("Co_body 0.5, each step")
c.legend(fontsize=7)

# Middle: the runs that did not diverge, averaged over 0.02 in time
for r in rows:
    if r["case"] != "moving" or r["RH"] not in ref or r["status"] != "ok":
        continue
    t, F = history(r["run"], r["RH"])
    if not t:
        continue
    k = max(1, int(round(0.02/float(r["dt"]))))
    k += k % 2
    ts = [sum(t[i:i + k])/k for i in range(len(t) - k + 1)]
    Fs = [sum(F[i:i + k])/k for i in range(len(F) - k + 1)]
    a.plot(ts, Fs, "-" if r["predictor"] == "lagged" else "--",
           lw=1.4 if float(r["Co_body"]) > 0.4 else 0.7,
           color=colours.get(r["RH"], "k"), label=r["run"])
a.axvspan(0.2, 0.4, color="0.9", zorder=0)
a.axhline(1, color="k", lw=0.5)
a.set_ylim(0.96, 1.04)
a.set_xlabel("t")
a.set_ylabel("drag / body-frame drag, mean over 0.02 in t")
a.set_title("runs that did not diverge (grey: averaging window)")
a.legend(fontsize=6)

# Right: the error of the mean drag
for pat, lab, m in (("moving-R%s-lagged", "lagged, Co_body 0.5", "o-"),
                    ("moving-R%s-lagged-nCorr4", "lagged, 4 PISO corr., Co_body 0.5", "v"),
                    ("moving-R%s-extrap-nCorr4", "extrapolated, 4 PISO corr., Co_body 0.5", "D-"),
                    ("moving-R%s-extrap-nCorr3", "extrapolated, 3 PISO corr., Co_body 0.5", "x--"),
                    ("moving-R%s-flux", "extrapolated flux only, Co_body 0.5", "P-"),
                    ("moving-R%s-flux-backward", "extrapolated flux only, backward, Co_body 0.5", "*-"),
                    ("moving-R%s-lagged-Co0.25", "lagged, Co_body 0.25", "^"),
                    ("moving-R%s-extrap-Co0.25", "extrapolated, Co_body 0.25", "s")):
    pts = sorted((float(r["RH"]), err(r)) for r in rows
                 if err(r) is not None and r["run"] == pat % r["RH"])
    if pts:
        b.plot([p[0] for p in pts], [p[1] for p in pts], m, label=lab)
b.axhspan(-1, 1, color="0.9", zorder=0)
b.axhline(0, color="k", lw=0.5)
b.set_xlabel("R/h")
b.set_ylabel("mean drag error vs body frame [%]")
b.set_title("mean drag, one outer corrector")
b.legend(fontsize=7)
fig.tight_layout()
fig.savefig("drag.png", dpi=100)
