"""Figures of a run of prm/barboteu2015.prm, in the manner of the paper's
Figure 2: the deformed body coloured by the von Mises stress, and the
friction traction with its bound along Gamma_3, at t = 0.3, 0.5, 0.8, 1.1.

Usage (ParaView's Python, Debian package paraview, and matplotlib):
    pvpython doc/plot_barboteu2015.py results-barboteu2015/solution.pvd doc/figures
"""
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
from matplotlib.collections import PolyCollection
import numpy as np
from paraview import servermanager
from paraview.simple import PVDReader
from vtk.util.numpy_support import vtk_to_numpy

pvd, out = sys.argv[1], sys.argv[2]
reader = PVDReader(FileName=pvd)
times = reader.TimestepValues


def snapshot(t):
    """Points, quads, point arrays of the output step nearest to t."""
    t_n = min(times, key=lambda s: abs(s - t))
    reader.UpdatePipeline(t_n)
    data = servermanager.Fetch(reader)
    if data.IsA("vtkMultiBlockDataSet"):
        data = data.GetBlock(0)
    points = vtk_to_numpy(data.GetPoints().GetData())[:, :2]
    cells = vtk_to_numpy(data.GetCells().GetData()).reshape(-1, 5)[:, 1:]
    arrays = {data.GetPointData().GetArrayName(i):
              vtk_to_numpy(data.GetPointData().GetArray(i))
              for i in range(data.GetPointData().GetNumberOfArrays())}
    return t_n, points, cells, arrays


snapshots = [snapshot(t) for t in (0.3, 0.5, 0.8, 1.1)]

figure, axes = plt.subplots(2, 2, figsize=(11, 4.6), constrained_layout=True)
vmax = max(s[3]["von_mises"].max() for s in snapshots)
for axis, (t_n, points, cells, arrays) in zip(axes.flat, snapshots):
    deformed = points + arrays["displacement"][:, :2]
    polygons = PolyCollection(deformed[cells], array=arrays["von_mises"][cells].mean(axis=1),
                              cmap="viridis", edgecolors="none")
    polygons.set_clim(0, vmax)
    axis.add_collection(polygons)
    on_gamma3 = arrays["contact_status"] > 0
    slip = arrays["contact_status"] == 2
    axis.plot(*deformed[on_gamma3 & ~slip].T, "s", color="tab:blue", ms=2, label="stick")
    axis.plot(*deformed[slip].T, "s", color="tab:red", ms=2, label="slip")
    # VTU points repeat at cell corners: count the nodes by their x.
    n_stick = len(np.unique(points[on_gamma3 & ~slip, 0]))
    n_slip = len(np.unique(points[slip, 0]))
    axis.set_title(f"t = {t_n:.3f} s: {n_stick} stick / {n_slip} slip nodes on Γ3")
    axis.set_aspect("equal")
    axis.set_xlim(-0.05, 1.25)
    axis.set_ylim(-0.05, 0.55)
    axis.legend(loc="lower right", fontsize=8)
figure.colorbar(polygons, ax=axes, label="von Mises stress [N/m²]")
figure.savefig(os.path.join(out, "barboteu2015_deformed.png"), dpi=110)

figure, axes = plt.subplots(1, 4, figsize=(14, 3.4), sharey=True, constrained_layout=True)
for axis, (t_n, points, cells, arrays) in zip(axes, snapshots):
    on_gamma3 = arrays["contact_status"] > 0
    x = points[on_gamma3, 0]
    order = np.argsort(x)
    x = x[order]
    traction = arrays["friction_traction"][on_gamma3, 0][order]
    bound = arrays["friction_bound"][on_gamma3][order]
    slip = (arrays["contact_status"][on_gamma3] == 2)[order]
    axis.plot(x, bound, "k-", lw=1, label="bound μ(|w_τ|) S")
    axis.plot(x, -bound, "k-", lw=1)
    axis.plot(x, traction, "-", color="tab:gray", lw=1)
    axis.plot(x[~slip], traction[~slip], ".", color="tab:blue", label="stick")
    axis.plot(x[slip], traction[slip], ".", color="tab:red", label="slip")
    axis.set_title(f"t = {t_n:.3f} s")
    axis.set_xlabel("x on Γ3 [m]")
axes[0].set_ylabel("friction traction [N/m]")
axes[0].legend(fontsize=8)
figure.savefig(os.path.join(out, "barboteu2015_gamma3.png"), dpi=110)
