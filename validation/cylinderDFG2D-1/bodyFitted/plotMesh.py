#!/usr/bin/python3
"""Draw a body-fitted DFG 2D-1 mesh (blockMesh O-grid) as mesh.png.

Reads the ascii constant/polyMesh (points, faces, boundary) of a case and
draws the faces of its frontAndBack patch at z < 0: the whole channel and
the cylinder close up.

Usage:
    plotMesh.py [CASE] [-o mesh.png]      (default CASE: runs/simpleFoam-level1)

Run it with Debian's python3 (/usr/bin/python3, python3-matplotlib).
"""

import argparse
import os
import re

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))


def list_body(path):
    """Text between the outer parentheses of an OpenFOAM ascii list file."""
    with open(path) as f:
        text = f.read()
    text = re.sub(r"/\*.*?\*/", "", text, flags=re.S)
    text = re.sub(r"//[^\n]*", "", text)
    text = text[text.index("}") + 1:]  # after the FoamFile header
    return text[text.index("(") + 1:text.rindex(")")]


def read_points(path):
    return [tuple(float(v) for v in m.split())
            for m in re.findall(r"\(([^()]*)\)", list_body(path))]


def read_faces(path):
    return [[int(v) for v in m.split()]
            for m in re.findall(r"\d+\(([^()]*)\)", list_body(path))]


def read_patch(path, name):
    """startFace and nFaces of patch name."""
    body = list_body(path)
    m = re.search(name + r"\s*\{([^}]*)\}", body)
    entries = dict(re.findall(r"(\w+)\s+([^;]+);", m.group(1)))
    return int(entries["startFace"]), int(entries["nFaces"])


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("case", nargs="?",
                        default=os.path.join(HERE, "runs", "simpleFoam-level1"))
    parser.add_argument("-o", "--output", default=os.path.join(HERE, "mesh.png"))
    args = parser.parse_args()

    mesh = os.path.join(args.case, "constant", "polyMesh")
    points = read_points(os.path.join(mesh, "points"))
    faces = read_faces(os.path.join(mesh, "faces"))
    start, size = read_patch(os.path.join(mesh, "boundary"), "frontAndBack")

    polygons = []
    for face in faces[start:start + size]:
        xyz = [points[i] for i in face]
        if all(p[2] < 0 for p in xyz):
            polygons.append([(p[0], p[1]) for p in xyz])

    fig, axes = plt.subplots(2, 1, figsize=(11, 8.5),
                             gridspec_kw={"height_ratios": [1, 2.2]})
    for ax, (xlim, ylim) in zip(axes, (((0, 2.2), (0, 0.41)),
                                       ((0, 0.5), (0, 0.41)))):
        ax.add_collection(PolyCollection(polygons, facecolors="none",
                                         edgecolors="k", linewidths=0.3))
        ax.set_xlim(*xlim)
        ax.set_ylim(*ylim)
        ax.set_aspect("equal")
        ax.set_xlabel("x")
        ax.set_ylabel("y")
    axes[0].set_title(f"{os.path.basename(os.path.abspath(args.case))}: "
                      f"{len(polygons):,} cells")
    axes[1].plot([0.15, 0.25], [0.2, 0.2], "o", color="C3", ms=4,
                 label="probes (0.15, 0.2), (0.25, 0.2)")
    axes[1].legend(loc="upper right", fontsize="small")
    fig.tight_layout()
    fig.savefig(args.output, dpi=110)
    print(f"Wrote {args.output}")


if __name__ == "__main__":
    main()
