"""Fig. 12 of Ulven & Sun (2017): pressure and fracture development around a pressurised borehole,
Q = 0.01, iota = 1, b = 0.2 (top row) and b = 0.8 (bottom row), at the case's output times.

Reads what `hmlattice run` writes for a fracturing case (the VTK snapshots vtk/lattice.pvd +
lattice_NNNN.vtu and fracture_summary.csv), either one run folder or a folder with runs.csv (written by
the lattice2d.fig12 benchmarks: one row per run folder, `figure` = 1 for the runs to draw):

    /usr/bin/python3 figures/fig12_fracture_pressure.py --data out/fig12_b0.2_quick --out fig
    /usr/bin/python3 figures/fig12_fracture_pressure.py --data verify/data/fig12_quick --out fig

Each panel: the pressure per triangle (undeformed lattice; diverging colours centred on p* = 0, limits
from that snapshot's min and max, as the paper's colour bars), broken beams as black segments (the beam
from particle i to j, so a crack shows as a chain of short segments across it), the borehole wall.
"""
import csv
import os
import xml.etree.ElementTree as ET

import matplotlib.colors as mcolors
import meshio
import numpy as np
from matplotlib.collections import LineCollection

import hmplot
from hmplot import plt


def runs_to_draw(data):
    """[(label, folder)] of the runs to draw."""
    index = os.path.join(data, "runs.csv")
    if os.path.exists(index):
        with open(index, newline="") as f:
            rows = [r for r in csv.DictReader(f) if r["figure"] == "1"]
        return [(r["run"], os.path.join(data, r["run"])) for r in sorted(rows, key=lambda r: float(r["b"]))]
    return [(os.path.basename(os.path.normpath(data)), data)]


def snapshots(folder):
    """[(t, .vtu path)] listed in vtk/lattice.pvd, t > 0 only."""
    pvd = os.path.join(folder, "vtk", "lattice.pvd")
    root = ET.parse(pvd).getroot()
    out = []
    for ds in root.iter("DataSet"):
        t = float(ds.get("timestep"))
        if t > 0.0:
            out.append((t, os.path.join(folder, "vtk", ds.get("file"))))
    return out


def read_snapshot(path):
    """Points, triangles with their pressure, broken-beam segments, borehole-wall points (in order)."""
    mesh = meshio.read(path)
    tri, p, seg = None, None, []
    for k, block in enumerate(mesh.cells):
        if block.type == "triangle":
            tri, p = block.data, np.asarray(mesh.cell_data["pressure"][k])
        elif block.type == "line":
            broken = np.asarray(mesh.cell_data["broken"][k]) == 1
            seg = block.data[broken]
    xy = mesh.points[:, :2]
    wall = xy[np.asarray(mesh.point_data["boundary"]) == 2]
    if len(wall):
        wall = wall[np.argsort(np.arctan2(wall[:, 1], wall[:, 0]))]
        wall = np.vstack([wall, wall[:1]])
    return xy, tri, p, xy[seg] if len(seg) else np.zeros((0, 2, 2)), wall


def summary_at(folder, t):
    """The fracture_summary.csv row at time t (or None)."""
    path = os.path.join(folder, "fracture_summary.csv")
    if not os.path.exists(path):
        return None
    s = hmplot.read_csv(path)
    k = np.argmin(np.abs(s["t"] - t))
    return {name: col[k] for name, col in s.items()} if abs(s["t"][k] - t) <= 1e-6 * t else None


def main():
    args = hmplot.arguments(__doc__.splitlines()[0])
    runs = [(label, folder, snapshots(folder)) for label, folder in runs_to_draw(args.data)]
    n_cols = max(len(s) for _, _, s in runs)
    fig, axes = plt.subplots(len(runs), n_cols, figsize=(3.0 * n_cols, 3.0 * len(runs)), squeeze=False)
    panel = iter("ABCDEFGHIJKLMNOP")
    for row, (label, folder, snaps) in enumerate(runs):
        b = hmplot.run_physics(folder, "b")
        for col in range(n_cols):
            ax = axes[row][col]
            if col >= len(snaps):
                ax.axis("off")
                continue
            t, path = snaps[col]
            xy, tri, p, seg, wall = read_snapshot(path)
            p_min, p_max = float(p.min()), float(p.max())
            # Centred on 0 like the paper's colour bars; TwoSlopeNorm needs vmin < 0 < vmax.
            scale = max(abs(p_min), abs(p_max), 1e-30)
            norm = mcolors.TwoSlopeNorm(vmin=min(p_min, -1e-6 * scale), vcenter=0.0, vmax=max(p_max, 1e-6 * scale))
            im = ax.tripcolor(xy[:, 0], xy[:, 1], tri, facecolors=p, cmap="RdBu_r", norm=norm, rasterized=True)
            if len(seg):
                ax.add_collection(LineCollection(seg, colors="k", linewidths=0.7))
            if len(wall):
                ax.plot(wall[:, 0], wall[:, 1], color="0.3", lw=0.6)
            ax.set_aspect("equal")
            ax.set_xlim(-1.02, 1.02)
            ax.set_ylim(-1.02, 1.02)
            ax.set_xticks([-1, 0, 1])
            ax.set_yticks([-1, 0, 1])
            ax.grid(False)
            s = summary_at(folder, t)
            counts = ""
            if s is not None:
                counts = (f"\n{int(s['n_radial'])} radial clusters, {int(s['n_arms'])} arms, "
                          f"{int(s['n_broken'])} broken")
            b_text = f"b = {b:g}, " if b is not None else ""
            ax.set_title(f"{next(panel)}: {b_text}t* = {t:.3g}{counts}", fontsize=8)
            cb = fig.colorbar(im, ax=ax, fraction=0.046, pad=0.03)
            cb.set_ticks([p_min, 0.0, p_max] if p_min < 0 < p_max else [p_min, p_max])
            cb.ax.tick_params(labelsize=7)
            cb.formatter = plt.FuncFormatter(lambda v, _: f"{v:.2e}")
            cb.update_ticks()
            if col == 0:
                ax.set_ylabel(f"{label}\ny*")
            if row == len(runs) - 1:
                ax.set_xlabel("x*")
    fig.suptitle("Pressure p* per triangle and broken beams (black); Q = 0.01, iota = 1", fontsize=10)
    hmplot.save(fig, args.out, "fig12_fracture_pressure")


if __name__ == "__main__":
    main()
