#!/usr/bin/python3
"""Chart of the settlingSphere mesh study (./Allrun, collect.py).

speed.png, from history.csv and results.csv / convergence.csv:
  left   the sphere's settling speed |U| against time, one colour per
         R/h (3, 4, 6), one line style per variant: the explicit
         coupling (addedMassCoeff 2), coupling semiImplicit
         (maxViscousRatio 5), each with the lagged and the extrapolated
         predictor
  right  the speed at t = 0.25 (filled markers) and its mean over
         t = 0.2-0.25 (open markers) against the cell size h for both
         couplings, with the Richardson-extrapolated value of the mean at h = 0 (star)
         where the three levels converge monotonically (convergence.csv)

Usage: /usr/bin/python3 plot.py     (Debian's python3 with matplotlib)
"""
import csv
import os

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
COLOURS = {"3": "tab:blue", "4": "tab:orange", "6": "tab:green"}
STYLES = {"explicit": ("-", "o", "explicit, addedMassCoeff 2"),
          "semiImplicit": ("--", "s", "semiImplicit, maxViscousRatio 5"),
          "explicitExtrap": ("-.", "^", "explicit, extrapolated flux"),
          "semiImplicitExtrap": (":", "D",
                                 "semiImplicit, extrapolated flux"),
          "explicitExtrapP": ((0, (5, 1)), "v", "explicit, extrapolated flux"
                              " and pressure, 3 PISO correctors"),
          "explicitExtrapBackward": ((0, (1, 1)), "*", "explicit, extrapolated"
                                     " flux, backward"),
          "semiImplicitExtrapBackward": ((0, (3, 1, 1, 1)), "P",
                                         "semiImplicit, extrapolated flux,"
                                         " backward, body Euler"),
          "semiImplicitExtrapBackwardF": ((0, (3, 1, 1, 1, 1, 1)), "X",
                                          "semiImplicit, extrapolated flux,"
                                          " backward, body at the fluid's"
                                          " rate"),
          "semiImplicitExtrapBackwardN": ((0, (6, 2)), "d",
                                          "semiImplicit, extrapolated flux,"
                                          " backward, pressureSolve newton")}


def read(name):
    path = os.path.join(HERE, name)
    return list(csv.DictReader(open(path))) if os.path.isfile(path) else []


def variant(r):
    return r.get("variant") or r["run"].split("-RH")[0]


def main():
    results = [r for r in read("results.csv") if r["body"] == "sphere"
               and variant(r) in STYLES]
    history = read("history.csv")
    conv = read("convergence.csv")
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(15, 5))
    for r in results:
        t = [float(h["t"]) for h in history if h["run"] == r["run"]]
        u = [float(h["speed"]) for h in history if h["run"] == r["run"]]
        style = STYLES[variant(r)][0]
        ax1.plot(t, u, linestyle=style, color=COLOURS.get(r["R_h"], "k"),
                 lw=1.2,
                 label="R/h %s, %s (%s cells)"
                 % (r["R_h"], variant(r), format(int(r["cells"]), ",")))
    ax1.set_xlabel("t")
    ax1.set_ylabel("settling speed |U|")
    ax1.set_xlim(0, 0.25)
    ax1.set_ylim(0, None)
    ax1.grid(alpha=0.3)
    ax1.legend(fontsize=7, loc="lower right")
    ax1.set_title("sphere d = 0.1, rho_s 1.5, nu 0.1, box 0.5 x 1 x 0.5",
                  fontsize=9)

    hMax = max([float(r["h"]) for r in results] + [0.01])
    for coupling, (style, marker, label) in STYLES.items():
        rows = sorted((r for r in results if variant(r) == coupling
                       and r["speed_0.25"]), key=lambda r: float(r["h"]))
        if not rows:
            continue
        h = [float(r["h"]) for r in rows]
        colour = None
        for key, t, fill in (("speed_0.25", "0.25", "full"),
                             ("mean_0.2_0.25", "0.2-0.25", "none")):
            u = [float(r[key]) for r in rows]
            line, = ax2.plot(h, u, linestyle=style, marker=marker,
                             color=colour,
                             fillstyle=fill, lw=1.2 if fill == "full"
                             else 0.8,
                             label="%s: %s" % (label, "at t = 0.25"
                                               if fill == "full" else
                                               "mean over t = 0.2-0.25"))
            colour = line.get_color()
            if fill == "full":
                for r, hi, ui in zip(rows, h, u):
                    ax2.annotate("R/h %s" % r["R_h"], (hi, ui), fontsize=7,
                                 textcoords="offset points", xytext=(4, 4))
            ext = [c for c in conv if c["coupling"] == coupling
                   and c["t"] == t and c["extrapolated"]
                   and t == "0.2-0.25"]
            if ext:
                e = float(ext[0]["extrapolated"])
                ax2.plot([0, h[0]], [e, u[0]], ":", color=colour, lw=0.8)
                ax2.plot([0], [e], "*", color=colour, ms=9,
                         fillstyle=fill,
                         label="Richardson (order %s)" % ext[0]["order"])
    ax2.set_xlabel("cell size h (sphere radius 0.05)")
    ax2.set_ylabel("settling speed")
    ax2.set_xlim(0, 1.15*hMax)
    ax2.grid(alpha=0.3)
    ax2.legend(fontsize=6, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "speed.png"), dpi=120)
    print("Wrote speed.png")


if __name__ == "__main__":
    main()
