#!/usr/bin/env python3
"""Pictures of a run of `contact`, from its output directory alone.

    python3 doc/plot_run.py results-barboteu2015
    python3 doc/plot_run.py results-barboteu2015_3d --field displacement --times 0.5,1

writes into <directory>/figures/ (or --output):

  deformed.png         the deformed body coloured by --field (default
                       cell_von_mises) at the chosen times, the nodes of
                       Gamma_3 marked stick (blue) or slip (red); in 3D the
                       body's boundary seen from above and, beside it, a
                       map of Gamma_3 with each face coloured by the share
                       of its nodes that slip
  mesh.png             the mesh at the chosen times (a mesh adapted during
                       the run changes): in 2D every cell, in 3D the faces
                       of Gamma_3 on its map, each coloured by its level of
                       refinement below the largest cells, the nodes of
                       Gamma_3 marked stick or slip
  gamma3_profiles.png  along Gamma_3 at the chosen times: the friction
                       traction against its bound mu(|w_tau|) S, and the slip
                       rate |w_tau|
  stick_slip.png       the space-time diagram of the stick/slip state on
                       Gamma_3 (coordinate against time; in 3D the fraction
                       of slipping nodes at each coordinate value)
  energies.png         energies and dissipations, the self-check residuals
                       and the iteration counts per step
  convergence.png      for a convergence study (convergence.txt): every
                       error against h (or k, when only k changes) and
                       against the wall time of each level

Along Gamma_3 the figures use the coordinate in which it extends furthest,
or, where Gamma_3 is a circle or a cylinder about the z-axis (a shell's
inner or outer boundary), the angle atan2(y, x) in degrees.

Each figure needs its own file: deformed.png the VTU output (solution.pvd),
the Gamma_3 figures gamma3_history.csv, energies.png time_series.csv; a
figure whose file is missing is skipped with a note. The chosen times
default to the run's Report times (or four evenly spaced times up to its
End time); each is moved to the nearest step that has the data. For every
figure the script prints what it shows (cells, stick/slip nodes at each
time, nodes above their bound, when slip starts, ...). Quadrilaterals,
hexahedra, triangles (P1, P2) and tetrahedra are drawn.

Needs only numpy and matplotlib (Debian: python3-numpy python3-matplotlib)
and no display: the VTU files are read here, not by ParaView.
"""
import argparse
import base64
import os
import re
import sys
import xml.etree.ElementTree as ElementTree
import zlib

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np
    from matplotlib.collections import PolyCollection
    from matplotlib.colors import LinearSegmentedColormap
    from mpl_toolkits.mplot3d import proj3d
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection
except ImportError as missing:
    sys.exit(f"plot_run.py needs numpy and matplotlib ({missing}). "
             "Debian: apt-get install python3-numpy python3-matplotlib; "
             "elsewhere: pip install numpy matplotlib")

STICK, SLIP = 1, 2
STATE_COLOURS = {STICK: "tab:blue", SLIP: "tab:red"}
STATE_MAP = LinearSegmentedColormap.from_list(
    "stick_slip", [STATE_COLOURS[STICK], STATE_COLOURS[SLIP]])
DPI = 110

# The SI unit of each field of the VTU output (stresses and tractions in
# Pa = N/m^2, in 2D as in 3D).
FIELD_UNITS = {"displacement": "m", "velocity": "m/s",
               "friction_traction": "Pa", "slip_rate": "m/s",
               "friction_bound": "Pa", "contact_status": "1 stick, 2 slip",
               "cell_von_mises": "Pa"}


def field_label(field):
    unit = FIELD_UNITS.get(field, "Pa" if field.startswith("cell_stress")
                           else None)
    return f"{field} [{unit}]" if unit else field


def outside_legend(axis):
    """The legend beside the axes, off the data."""
    axis.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1),
                borderaxespad=0)


# @sect3{Reading the VTU output}
#
# deal.II writes binary VTU files: each data array is base64 text of a
# header of unsigned 32-bit integers (number of blocks, block size, size
# of the last block, compressed size of each block) followed by the
# zlib-compressed blocks, or without a compressor one integer (the byte
# count) followed by the raw data. Every cell has its own copy of its
# vertices, so cell data is constant over a cell's points.

# The VTK cell types deal.II writes: for each, the dimension, the corners
# in the order that walks around a 2D cell's boundary (quadratic triangles
# list their corners first and then the edge midpoints), and a 3D cell's
# faces as lists of corners.
CELL_TYPES = {
    5: (2, [0, 1, 2], None),                                  # triangle
    22: (2, [0, 3, 1, 4, 2, 5], None),                        # quadratic
    9: (2, [0, 1, 2, 3], None),                               # quadrilateral
    10: (3, None, [[0, 1, 2], [0, 1, 3], [1, 2, 3], [0, 2, 3]]),  # tetrahedron
    24: (3, None, [[0, 1, 2], [0, 1, 3], [1, 2, 3], [0, 2, 3]]),  # quadratic
    12: (3, None, [[0, 1, 2, 3], [4, 5, 6, 7], [0, 1, 5, 4],  # hexahedron
                   [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]]),
}

VTK_TYPES = {"Float32": np.float32, "Float64": np.float64,
             "Int32": np.int32, "Int64": np.int64, "UInt8": np.uint8,
             "UInt32": np.uint32, "UInt64": np.uint64}


def decode_binary(text, dtype, compressed):
    text = "".join(text.split())
    if not compressed:
        raw = base64.b64decode(text)
        return np.frombuffer(raw[4:], dtype=dtype)
    n_blocks = int(np.frombuffer(base64.b64decode(text[:8])[:4], np.uint32)[0])
    header_chars = 4 * -(-(3 + n_blocks) * 4 // 3)
    header = np.frombuffer(base64.b64decode(text[:header_chars]),
                           np.uint32)[:3 + n_blocks]
    data = base64.b64decode(text[header_chars:])
    blocks, start = [], 0
    for size in header[3:]:
        blocks.append(zlib.decompress(data[start:start + size]))
        start += size
    return np.frombuffer(b"".join(blocks), dtype=dtype)


def read_data_array(element, compressed):
    dtype = VTK_TYPES[element.get("type")]
    if element.get("format") == "ascii":
        values = np.array(element.text.split(), dtype=dtype)
    else:
        values = decode_binary(element.text, dtype, compressed)
    components = int(element.get("NumberOfComponents", "1"))
    return values.reshape(-1, components) if components > 1 else values


def read_vtu(path):
    """Points, cells (point indices per cell), the VTK cell type and the
    point arrays of a piece (deal.II writes one cell type per file)."""
    root = ElementTree.parse(path).getroot()
    compressed = root.get("compressor") is not None
    piece = root.find("UnstructuredGrid/Piece")
    points = read_data_array(piece.find("Points/DataArray"), compressed)
    cell_arrays = {a.get("Name"): read_data_array(a, compressed)
                   for a in piece.find("Cells")}
    offsets = cell_arrays["offsets"]
    vertices_per_cell = offsets[0]
    cells = cell_arrays["connectivity"].reshape(-1, vertices_per_cell)
    cell_type = int(cell_arrays["types"][0])
    if cell_type not in CELL_TYPES:
        sys.exit(f"plot_run.py: {path}: VTK cell type {cell_type} is not "
                 f"one this script draws ({sorted(CELL_TYPES)})")
    arrays = {}
    point_data = piece.find("PointData")
    if point_data is not None:
        arrays = {a.get("Name"): read_data_array(a, compressed)
                  for a in point_data}
    return points, cells, cell_type, arrays


def damaged(path, error):
    """Ends the script naming a file it cannot read."""
    sys.exit(f"plot_run.py: cannot read {path}: {error} (a run killed "
             "while writing it, or a damaged copy?)")


def read_snapshot(directory, record):
    """All pieces of one output step (a .pvtu or .vtu file), merged: the
    points, the cells, their VTK type and the point arrays."""
    path = os.path.join(directory, record)
    pieces = [path]
    if path.endswith(".pvtu"):
        try:
            root = ElementTree.parse(path).getroot()
        except (OSError, ElementTree.ParseError) as error:
            damaged(path, error)
        pieces = [os.path.join(os.path.dirname(path), p.get("Source"))
                  for p in root.iter("Piece")]
    all_points, all_cells, all_arrays, offset = [], [], {}, 0
    for piece in pieces:
        try:
            points, cells, cell_type, arrays = read_vtu(piece)
        except (OSError, ElementTree.ParseError, ValueError, KeyError,
                AttributeError, TypeError, zlib.error) as error:
            damaged(piece, error)
        all_points.append(points)
        all_cells.append(cells + offset)
        offset += len(points)
        for name, values in arrays.items():
            all_arrays.setdefault(name, []).append(values)
    return (np.concatenate(all_points), np.concatenate(all_cells), cell_type,
            {name: np.concatenate(v) for name, v in all_arrays.items()})


def read_pvd(directory):
    """(time, file) of every output step listed in solution.pvd."""
    path = os.path.join(directory, "solution.pvd")
    if not os.path.exists(path):
        return []
    try:
        root = ElementTree.parse(path).getroot()
    except ElementTree.ParseError as error:
        damaged(path, error)
    return [(float(d.get("timestep")), d.get("file"))
            for d in root.iter("DataSet")]


# @sect3{Reading the CSV files and the parameters}

def read_csv(path):
    """A CSV file with a header line as a dict of numpy columns. A last row
    cut short (a run killed while writing it) is left out with a note; any
    other row that is not numbers ends the script naming its line."""
    with open(path) as file:
        lines = file.read().split("\n")
    if not lines[0].strip():
        return {}
    names = lines[0].strip().split(",")
    rows = [line for line in lines[1:] if line.strip()]
    if rows and lines[-1].strip():
        print(f"note: {path}: its last row is cut short (a run killed while "
              "writing it?); it is left out")
        rows = rows[:-1]
    values = np.zeros((len(rows), len(names)))
    for number, row in enumerate(rows):
        fields = row.split(",")
        try:
            if len(fields) != len(names):
                raise ValueError(f"{len(fields)} fields, the header has "
                                 f"{len(names)}")
            values[number] = [float(f) for f in fields]
        except ValueError as error:
            damaged(path, f"line {number + 2}: {error}")
    return {name: values[:, i] for i, name in enumerate(names)}


def read_parameter(directory, name):
    """The value of `set <name> = ...` in the run's parameters.prm."""
    path = os.path.join(directory, "parameters.prm")
    if not os.path.exists(path):
        return None
    for line in open(path):
        match = re.match(r"\s*set\s+" + re.escape(name) + r"\s*=\s*(.*)", line)
        if match:
            return match.group(1).split("#")[0].strip()
    return None


def read_org_table(path):
    rows = [[c.strip() for c in line.strip().strip("|").split("|")]
            for line in open(path) if line.startswith("|")]
    header, body = rows[0], rows[1:]
    return {name: [row[i] for row in body] for i, name in enumerate(header)}


def chosen_times(arguments, directory, last_time, end_time):
    """The times to draw: --times (each must lie in [0, last_time]), or the
    run's Report times up to its last step (a run that ended early, killed
    or still running, has no later states: those times are left out with
    a note), or four times up to the End time."""
    if arguments.times:
        times = []
        for text in arguments.times.split(","):
            try:
                t = float(text)
            except ValueError:
                sys.exit(f"plot_run.py: --times: '{text}' is not a number; "
                         "give times separated by ','")
            if not 0 <= t <= last_time:
                sys.exit(f"plot_run.py: --times: {text} is not a time of this "
                         f"run; allowed are times in [0, {last_time:g}]")
            times.append(t)
        return times
    if last_time < end_time * (1 - 1e-9):
        print(f"note: the run ends at t = {last_time:g}, before its End time "
              f"{end_time:g} (killed, or still running?)")
    report = read_parameter(directory, "Report times")
    if not report:
        return list(np.linspace(last_time / 4, last_time, 4))
    times = [float(t) for t in report.split(",")]
    later = [t for t in times if t > last_time * (1 + 1e-9)]
    if later:
        print(f"note: the Report times {', '.join(f'{t:g}' for t in later)} "
              "come after the run's last step and are not drawn")
    return [t for t in times if t not in later] or [last_time]


def nearest(available, t):
    return min(available, key=lambda s: abs(s - t))


# @sect3{The deformed body}
#
# Cells are drawn without antialiasing and without edges: antialiased
# polygons leave sub-pixel gaps to their neighbours, and edges drawn over
# them pile up where cells get thin in the picture; either shows up as a
# moire pattern or as dark streaks that are not in the data. All panels
# share one colour scale, so that a colour means the same value in each
# (the early, weakly loaded states are therefore dark).

def field_values(arrays, field, cells):
    if field not in arrays:
        sys.exit(f"plot_run.py: no field '{field}' in the VTU output; "
                 f"available: {', '.join(sorted(arrays))}")
    values = arrays[field]
    if values.ndim > 1:
        values = np.linalg.norm(values, axis=1)
    return values[cells].mean(axis=1)


def count_nodes(points, arrays, state):
    """Nodes of Gamma_3 in a state; the VTU repeats a node once per cell."""
    chosen = arrays["contact_status"] == state
    return len(np.unique(np.round(points[chosen], 9), axis=0))


def draw_deformed_2d(axis, points, cells, cell_type, arrays, field, limits):
    deformed = points[:, :2] + arrays["displacement"][:, :2]
    corners = cells[:, CELL_TYPES[cell_type][1]]
    polygons = PolyCollection(deformed[corners], array=field_values(
        arrays, field, cells), cmap="viridis", edgecolors="none",
        linewidths=0, antialiaseds=False)
    polygons.set_clim(*limits)
    axis.add_collection(polygons)
    for state, colour in STATE_COLOURS.items():
        chosen = arrays["contact_status"] == state
        axis.plot(*deformed[chosen].T, "s", color=colour, ms=2)
    axis.autoscale_view()
    axis.set_aspect("equal")
    axis.set_xlabel("x [m]")
    axis.set_ylabel("y [m]")
    return len(corners)


def boundary_faces(points, cells, cell_type):
    """The faces of 3D cells that belong to one cell only, and the cell
    each belongs to."""
    local_faces = CELL_TYPES[cell_type][2]
    n_corners = len(local_faces[0])
    faces = cells[:, np.array(local_faces)].reshape(-1, n_corners)
    keys = np.round(points[faces].mean(axis=1), 9)
    _, index, counts = np.unique(keys, axis=0, return_index=True,
                                 return_counts=True)
    return faces[index[counts == 1]], index[counts == 1] // len(local_faces)


def gamma3_faces(points, cells, cell_type, arrays):
    """The boundary faces on Gamma_3: those with all corners on it, and
    where Gamma_3 is flat also those in its plane with some corner on it
    (the nodes Gamma_3 shares with a clamp carry no status)."""
    faces, _ = boundary_faces(points, cells, cell_type)
    status = arrays["contact_status"][faces]
    on_gamma3 = (status > 0).all(axis=1)
    nodes = points[arrays["contact_status"] > 0]
    if len(nodes) == 0:
        return faces[on_gamma3]
    normal = int(np.argmin(np.ptp(nodes, axis=0)))
    extent = np.ptp(points, axis=0).max()
    if np.ptp(nodes[:, normal]) <= 1e-9 * extent:
        in_plane = (np.abs(points[faces][:, :, normal] - nodes[0, normal])
                    <= 1e-9 * extent).all(axis=1)
        on_gamma3 |= in_plane & (status > 0).any(axis=1)
    return faces[on_gamma3]


def gamma3_plane(corners):
    """The corners of Gamma_3's faces in its plane (the two coordinates in
    which it extends furthest), or, on a cylinder about the z-axis,
    unrolled to the angle atan2(y, x) and z; and the axes' labels."""
    radius = np.hypot(corners[:, :, 0], corners[:, :, 1])
    if radius.min() > 0 and np.ptp(radius) <= 1e-6 * radius.max():
        angle = np.degrees(np.arctan2(corners[:, :, 1], corners[:, :, 0]))
        # A face across +-180 degrees is drawn on the positive side.
        across = np.ptp(angle, axis=1) > 180
        angle[across] = np.where(angle[across] < 0, angle[across] + 360,
                                 angle[across])
        return (np.stack([angle, corners[:, :, 2]], axis=2),
                ("angle on Γ3 [°]", "z on Γ3 [m]"))
    in_plane = sorted(np.argsort(np.ptp(corners.reshape(-1, 3), axis=0))[1:])
    return (corners[:, :, in_plane],
            tuple(f"{'xyz'[c]} on Γ3 [m]" for c in in_plane))


def draw_gamma3_map(axis, points, cells, cell_type, arrays):
    """Gamma_3's faces in its plane (the two coordinates in which it
    extends furthest), or, on a cylinder about the z-axis, unrolled to the
    angle atan2(y, x) and z; coloured by the share of their nodes that
    slip. Returns the number of faces."""
    faces = gamma3_faces(points, cells, cell_type, arrays)
    if len(faces) == 0:
        axis.set_axis_off()
        return 0
    polygons_in_plane, labels = gamma3_plane(points[faces])
    polygons = PolyCollection(
        polygons_in_plane,
        facecolors=STATE_MAP((arrays["contact_status"][faces] == SLIP)
                             .mean(axis=1)),
        edgecolors="white", linewidths=0.3)
    axis.add_collection(polygons)
    axis.autoscale_view()
    if labels[0] != "angle on Γ3 [°]":
        axis.set_aspect("equal")
    axis.set_xlabel(labels[0])
    axis.set_ylabel(labels[1])
    return len(faces)


def draw_deformed_3d(axis, points, cells, cell_type, arrays, field, limits):
    """The boundary of the body seen from above: the vertical axis of the
    picture is the coordinate in which Gamma_3 extends least (its normal,
    for a flat Gamma_3). Where Gamma_3 is in view its faces are coloured
    by the share of their nodes that slip; the map beside it shows all of
    Gamma_3."""
    faces, owner = boundary_faces(points, cells, cell_type)
    colours = plt.get_cmap("viridis")(
        (field_values(arrays, field, cells)[owner] - limits[0]) /
        (limits[1] - limits[0]))
    status = arrays["contact_status"][faces]
    on_gamma3 = (status > 0).all(axis=1)
    colours[on_gamma3] = STATE_MAP((status[on_gamma3] == SLIP).mean(axis=1))
    nodes = points[arrays["contact_status"] > 0]
    vertical = int(np.argmin(np.ptp(nodes, axis=0))) if len(nodes) else 2
    order = [c for c in range(3) if c != vertical] + [vertical]
    deformed = (points + arrays["displacement"])[:, order]
    low, high = deformed.min(axis=0), deformed.max(axis=0)
    for set_limits, l, h in zip((axis.set_xlim, axis.set_ylim, axis.set_zlim),
                                low, high):
        set_limits(l, h)
    axis.set_box_aspect(high - low)
    axis.view_init(elev=25, azim=-60)
    # matplotlib sorts polygons by their mean depth, which draws hidden
    # faces over visible ones. So only the faces that face the viewer are
    # drawn (exact for a convex body): with its corners ordered so that
    # its normal points out of the body, such a face runs counterclockwise
    # on the screen.
    corners = deformed[faces]
    normal = np.cross(corners[:, 2] - corners[:, 0],
                      corners[:, -1] - corners[:, 1])
    outward = np.einsum("ij,ij->i", normal, corners.mean(axis=1) -
                        deformed[cells[owner]].mean(axis=1)) > 0
    x, y, _ = proj3d.proj_transform(*corners.reshape(-1, 3).T,
                                    axis.get_proj())
    x, y = x.reshape(corners.shape[:2]), y.reshape(corners.shape[:2])
    area = (x * np.roll(y, -1, axis=1) - np.roll(x, -1, axis=1) * y).sum(1)
    visible = (area > 0) == outward
    axis.add_collection3d(Poly3DCollection(
        corners[visible], facecolors=colours[visible], edgecolors="none",
        linewidths=0, antialiaseds=False))
    for set_label, c in zip((axis.set_xlabel, axis.set_ylabel,
                             axis.set_zlabel), order):
        set_label(f"{'xyz'[c]} [m]")


def plot_deformed(directory, times, field, output):
    """deformed.png; returns what it shows, or why it was skipped."""
    records = read_pvd(directory)
    if not records:
        return None, "no solution.pvd (Output/VTU interval = 0?)"
    steps = []
    for t in times:
        record = min(records, key=lambda r: abs(r[0] - t))
        if record not in steps:
            steps.append(record)
    snapshots = [(t, *read_snapshot(directory, f)) for t, f in steps]
    dim = CELL_TYPES[snapshots[0][3]][0]
    # Panels side by side unless the body is much wider than high.
    extent = np.ptp(snapshots[0][1], axis=0)
    aspect = extent[0] / max(extent[1], 1e-30) if dim == 2 else 1.5
    # In 3D each time gets a row: the body, and the map of Gamma_3.
    columns = 2 if dim == 3 else min(len(snapshots), 1 if aspect > 3 else 2)
    width = 11.0 / columns
    rows = len(snapshots) if dim == 3 else -(-len(snapshots) // columns)
    figure = plt.figure(
        figsize=(11.0, rows * (min(width / aspect, 5.0) + 0.8) + 0.6),
        constrained_layout=True)
    shown = []
    # One colour scale for all panels, so that their colours compare.
    values = np.concatenate([field_values(arrays, field, cells)
                             for _, _, cells, _, arrays in snapshots])
    limits = (values.min(), max(values.max(), values.min() + 1e-30))
    for i, (t, points, cells, cell_type, arrays) in enumerate(snapshots):
        n_stick = count_nodes(points, arrays, STICK)
        n_slip = count_nodes(points, arrays, SLIP)
        if dim == 2:
            axis = figure.add_subplot(rows, columns, i + 1)
            n_cells = draw_deformed_2d(axis, points, cells, cell_type, arrays,
                                       field, limits)
            shown.append(f"t = {t:.4g}: {n_cells} drawn cells, {n_stick} stick / "
                         f"{n_slip} slip nodes")
        else:
            n_faces = draw_gamma3_map(
                figure.add_subplot(rows, columns, 2 * i + 2), points, cells,
                cell_type, arrays)
            axis = figure.add_subplot(rows, columns, 2 * i + 1,
                                      projection="3d")
            draw_deformed_3d(axis, points, cells, cell_type, arrays, field,
                             limits)
            shown.append(f"t = {t:.4g}: {n_faces} faces of Γ3 on its map, "
                         f"{n_stick} stick / {n_slip} slip nodes")
        axis.set_title(f"t = {t:.4g}: {n_stick} stick, {n_slip} slip")
        figure.colorbar(plt.cm.ScalarMappable(
            norm=plt.Normalize(*limits), cmap="viridis"),
            ax=axis, label=field_label(field), shrink=0.7,
            pad=0.2 if dim == 3 else 0.05)
    figure.suptitle(f"deformed body coloured by {field} (one colour scale; "
                    "displacements drawn at true scale)\nΓ3: stick blue, "
                    "slip red" + (" (right: a face of Γ3 by the share of "
                                  "its nodes)" if dim == 3 else ""))
    figure.savefig(os.path.join(output, "deformed.png"), dpi=DPI)
    plt.close(figure)
    return "; ".join(shown), None


# @sect3{The mesh}

def cell_outlines(points, cells, cell_type, degree):
    """The corners of every mesh cell in 2D, counter-clockwise. deal.II
    writes a cell of degree p as one patch of p x p quadrilaterals with its
    (p + 1)^2 points in a block, in lexicographic order; a triangle is its
    own outline."""
    if cell_type == 9 and degree > 1:
        block = (degree + 1) ** 2
        patches = points[: len(points) // block * block].reshape(
            -1, block, points.shape[1])
        return patches[:, [0, degree, block - 1, block - 1 - degree], :2]
    corners = cells[:, CELL_TYPES[cell_type][1]]
    return points[corners][:, :, :2]


def refinement_levels(outlines):
    """Each polygon's level: log2 of the largest diameter over its own,
    rounded (a graded or adapted mesh's levels of refinement)."""
    diameters = np.array([max(np.linalg.norm(a - b) for a in polygon
                              for b in polygon) for polygon in outlines])
    return np.rint(np.log2(diameters.max() / diameters)).astype(int)


def draw_mesh(axis, polygons, levels, status_points, status, equal):
    """Polygons by level (discrete colours, black edges) and the nodes of
    Gamma_3 by their status."""
    colours = plt.cm.Blues(0.15 + 0.7 * levels / max(levels.max(), 1))
    axis.add_collection(PolyCollection(polygons, facecolors=colours,
                                       edgecolors="black", linewidths=0.2))
    for state, colour in STATE_COLOURS.items():
        axis.plot(*status_points[status == state].T, "o", color=colour, ms=2)
    axis.autoscale_view()
    if equal:
        axis.set_aspect("equal")


def plot_mesh(directory, times, output):
    """mesh.png; returns what it shows, or why it was skipped."""
    records = read_pvd(directory)
    if not records:
        return None, "no solution.pvd (Output/VTU interval = 0?)"
    degree = int(read_parameter(directory, "Finite element degree") or "1")
    steps = []
    for t in times:
        record = min(records, key=lambda r: abs(r[0] - t))
        if record not in steps:
            steps.append(record)
    figure, axes = plt.subplots(len(steps), 1, squeeze=False,
                                figsize=(11.0, 3.6 * len(steps)),
                                constrained_layout=True)
    shown, three_d = [], False
    for axis, (t, name) in zip(axes[:, 0], steps):
        points, cells, cell_type, arrays = read_snapshot(directory, name)
        status = arrays["contact_status"]
        if CELL_TYPES[cell_type][0] == 2:
            polygons = cell_outlines(points, cells, cell_type, degree)
            on_gamma3 = status > 0
            draw_mesh(axis, polygons, refinement_levels(polygons),
                      points[on_gamma3][:, :2], status[on_gamma3], True)
            axis.set_xlabel("x [m]")
            axis.set_ylabel("y [m]")
            what = f"{len(polygons)} cells"
        else:
            faces = gamma3_faces(points, cells, cell_type, arrays)
            if len(faces) == 0:
                axis.set_axis_off()
                shown.append(f"t = {t:.4g}: no faces of Γ3")
                continue
            polygons, labels = gamma3_plane(points[faces])
            # The nodes where the faces' corners are drawn.
            nodes, first = np.unique(faces, return_index=True)
            positions = polygons.reshape(-1, 2)[first]
            draw_mesh(axis, polygons, refinement_levels(polygons), positions,
                      status[nodes], labels[0] != "angle on Γ3 [°]")
            axis.set_xlabel(labels[0])
            axis.set_ylabel(labels[1])
            what = f"{len(polygons)} faces of Γ3"
        count = refinement_levels(polygons).max() + 1
        sizes = f"{count} size{'s' if count > 1 else ''}"
        axis.set_title(f"t = {t:.4g}: {what} of {sizes}" +
                       (" (darker: finer)" if count > 1 else ""))
        shown.append(f"t = {t:.4g}: {what} of {sizes}")
        three_d = CELL_TYPES[cell_type][0] == 3
    figure.suptitle("the mesh" + (" (the faces of Γ3 as the output's "
                                  "subcells)" if three_d and degree > 1
                                  else "") +
                    "; Γ3: stick blue, slip red")
    figure.savefig(os.path.join(output, "mesh.png"), dpi=DPI)
    plt.close(figure)
    return "; ".join(shown), None


# @sect3{Gamma_3: profiles and the space-time diagram}

def add_angle(history):
    """Where every node of Gamma_3 has the same distance from the z-axis
    (to 1e-6), the column 'angle', atan2(y, x) in degrees: the coordinate
    along a closed Gamma_3."""
    radius = np.hypot(history["x"], history["y"])
    if radius.min() > 0 and np.ptp(radius) <= 1e-6 * radius.max():
        history["angle"] = np.degrees(np.arctan2(history["y"], history["x"]))


def axis_label(coordinate):
    return ("angle on Γ3 [°]" if coordinate == "angle" else
            f"{coordinate} on Γ3 [m]")


def gamma3_coordinate(history, name):
    """The coordinate along which Gamma_3 is drawn: the one named, the
    angle about the z-axis where Gamma_3 is a circle or a cylinder about
    it, or the coordinate in which Gamma_3's nodes extend furthest."""
    coordinates = [c for c in ("x", "y", "z", "angle") if c in history]
    if name:
        if name not in coordinates:
            sys.exit(f"plot_run.py: --coordinate must be one of "
                     f"{', '.join(coordinates)}")
        if np.ptp(history[name]) == 0:
            sys.exit(f"plot_run.py: --coordinate {name}: every node of "
                     f"Gamma_3 has {name} = {history[name][0]:g}; choose one "
                     "along which Gamma_3 extends")
        return name
    if "angle" in history:
        return "angle"
    return max(coordinates, key=lambda c: np.ptp(history[c]))


def history_at(history, t):
    times = np.unique(history["time"])
    t_n = nearest(times, t)
    chosen = history["time"] == t_n
    return t_n, {name: values[chosen] for name, values in history.items()}


def plot_gamma3_map(axis, nodes, coordinate):
    """In 3D: Gamma_3's nodes in its plane (the coordinate along which the
    profiles run and the other one in which Gamma_3 extends furthest; z
    across the angle of a cylinder)."""
    others = [c for c in ("x", "y", "z") if c != coordinate]
    across = ("z" if coordinate == "angle" else
              max(others, key=lambda c: np.ptp(nodes[c])))
    axis.scatter(nodes[coordinate], nodes[across], s=6, marker="s",
                 c=nodes["state"] == SLIP, cmap=STATE_MAP, vmin=0, vmax=1)
    axis.set_ylabel(f"{across} on Γ3")
    if coordinate != "angle":
        axis.set_aspect("equal", adjustable="box")


def plot_gamma3_profiles(history, times, coordinate, output):
    traction_columns = [c for c in history if c.startswith(
        "friction_traction_t")]
    columns = len(times)
    rows = 3 if len(traction_columns) > 1 else 2
    figure, axes = plt.subplots(rows, columns,
                                figsize=(3.6 * columns + 0.5, 2.9 * rows),
                                sharex=True, sharey="row", squeeze=False,
                                constrained_layout=True)
    shown = []
    for column, t in enumerate(times):
        t_n, nodes = history_at(history, t)
        order = np.argsort(nodes[coordinate], kind="stable")
        s = nodes[coordinate][order]
        bound = nodes["friction_bound"][order]
        state = nodes["state"][order]
        if len(traction_columns) == 1:
            traction = nodes[traction_columns[0]][order]
            label = "friction traction t_1 [Pa]"
            axes[0, column].plot(s, -bound, "k-", lw=1)
            axes[0, column].plot(s, bound, "k-", lw=1,
                                 label="bound μ(|w_τ|) S")
        else:
            # In 3D several nodes share a coordinate value: points, not
            # lines, for the traction's length and for the bound.
            traction = np.linalg.norm(
                [nodes[c][order] for c in traction_columns], axis=0)
            label = "|friction traction| [Pa]"
            axes[0, column].plot(s, bound, "k_", ms=4,
                                 label="bound μ(|w_τ|) S")
        for value, colour in STATE_COLOURS.items():
            chosen = state == value
            axes[0, column].plot(s[chosen], traction[chosen], ".", ms=3,
                                 color=colour,
                                 label="stick" if value == STICK else "slip")
            axes[1, column].plot(s[chosen], nodes["slip_rate"][order][chosen],
                                 ".", ms=3, color=colour)
        axes[0, column].set_title(f"t = {t_n:.4g}")
        # What the picture must show: no node above its bound.
        above = np.abs(traction) > bound * (1 + 1e-6) + 1e-12
        shown.append(f"t = {t_n:.4g}: {len(s)} nodes, {int(above.sum())} "
                     "above the bound")
        if rows == 3:
            plot_gamma3_map(axes[2, column], nodes, coordinate)
        axes[-1, column].set_xlabel(axis_label(coordinate))
    axes[0, 0].set_ylabel(label)
    axes[1, 0].set_ylabel("slip rate |w_τ| [m/s]")
    handles, labels = axes[0, 0].get_legend_handles_labels()
    axes[0, -1].legend(handles, labels, fontsize=7, loc="upper left",
                       bbox_to_anchor=(1.01, 1), borderaxespad=0)
    figure.savefig(os.path.join(output, "gamma3_profiles.png"), dpi=DPI)
    plt.close(figure)
    return "; ".join(shown)


def plot_stick_slip(history, coordinate, output):
    """Slip fraction in cells of (coordinate value, step): in 2D every cell
    holds one node, in 3D all nodes of Gamma_3 with that coordinate."""
    positions = np.round(history[coordinate], 9)
    values = np.unique(positions)
    if len(values) > 400:
        values = np.linspace(values.min(), values.max(), 201)
        column = np.clip(np.searchsorted(values, positions) - 1, 0, 199)
        edges_s = values
    else:
        column = np.searchsorted(values, positions)
        middles = (values[1:] + values[:-1]) / 2
        edges_s = np.concatenate(([values[0] - (middles[0] - values[0])
                                   if len(values) > 1 else values[0] - 0.5],
                                  middles,
                                  [values[-1] + (values[-1] - middles[-1])
                                   if len(values) > 1 else values[0] + 0.5]))
    steps = history["step"].astype(int)
    step_values, row = np.unique(steps, return_inverse=True)
    step_times = np.array([history["time"][steps == s][0]
                           for s in step_values])
    slipping = np.zeros((len(step_values), len(edges_s) - 1))
    counts = np.zeros_like(slipping)
    np.add.at(slipping, (row, column), history["state"] == SLIP)
    np.add.at(counts, (row, column), 1)
    fraction = np.divide(slipping, counts, out=np.full_like(slipping, np.nan),
                         where=counts > 0)
    middles_t = (step_times[1:] + step_times[:-1]) / 2
    edges_t = np.concatenate(([step_times[0]], middles_t, [step_times[-1]]))
    figure, axis = plt.subplots(figsize=(7, 4.5), constrained_layout=True)
    mesh = axis.pcolormesh(edges_s, edges_t, fraction, shading="flat",
                           cmap=STATE_MAP, vmin=0, vmax=1, rasterized=True)
    axis.set_xlabel(axis_label(coordinate))
    axis.set_ylabel("t [s]")
    axis.set_title("stick (blue) and slip (red) on Γ3")
    if "z" in history:
        figure.colorbar(mesh, ax=axis, label="fraction of nodes slipping")
    figure.savefig(os.path.join(output, "stick_slip.png"), dpi=DPI)
    plt.close(figure)
    slip_rows = np.nonzero(np.nan_to_num(fraction).max(axis=1) > 0)[0]
    first = (f"the first step with slip ends at t = "
             f"{step_times[slip_rows[0]]:.4g}"
             if len(slip_rows) else "no slip")
    return (f"{len(step_values)} steps x {len(edges_s) - 1} positions along "
            f"{coordinate}; {first}")


# @sect3{Energies, self-checks, iterations}

def plot_energies(series, output):
    t = series["time"]
    figure, (energies, residuals, iterations) = plt.subplots(
        1, 3, figsize=(15, 4), constrained_layout=True)
    # (mesh_transfer: a run whose mesh changed during it.)
    for name in ("kinetic_energy", "elastic_energy", "external_work",
                 "viscous_dissipation", "friction_dissipation",
                 "numerical_dissipation", "mesh_transfer"):
        if name in series:
            energies.plot(t, series[name], label=name.replace("_", " "))
    energies.set_xlabel("t [s]")
    # In 2D per metre of thickness (plane strain).
    energies.set_ylabel("energy [J]" if "momentum_z" in series else
                        "energy [J/m]")
    outside_legend(energies)
    for name in ("load_power_residual", "constraint_residual",
                 "equation_residual", "friction_law_residual", "stick_speed"):
        # Exact zeros (no slip yet, nothing to violate) are left out.
        values = np.abs(series[name][1:])
        residuals.semilogy(t[1:], np.where(values > 0, values, np.nan),
                           label=name.replace("_", " "))
    residuals.set_xlabel("t [s]")
    residuals.set_ylabel("relative residual [1]")
    residuals.set_title("self-checks (round-off when the solve is right)")
    outside_legend(residuals)
    for name in ("convexification_iterations", "active_set_iterations",
                 "n_stick", "n_slip"):
        iterations.plot(t[1:], series[name][1:], label=name.replace("_", " "))
    iterations.set_xlabel("t [s]")
    iterations.set_ylabel("count")
    outside_legend(iterations)
    figure.savefig(os.path.join(output, "energies.png"), dpi=DPI)
    plt.close(figure)
    return (f"{len(t) - 1} steps to t = {t[-1]:.4g}; external work "
            f"{series['external_work'][-1]:.4g}")


# @sect3{A convergence study}

def plot_convergence(path, output):
    table = read_org_table(path)
    h = np.array(table["h"], dtype=float)
    k = np.array(table["k"], dtype=float)
    step, step_name = (h, "h") if np.ptp(h) > 0 else (k, "k")
    with_time = "wall time [s]" in table
    figure, axes = plt.subplots(1, 2 if with_time else 1, squeeze=False,
                                figsize=(11 if with_time else 5.5, 4.2),
                                constrained_layout=True)
    errors = {column: np.array(values, dtype=float)
              for column, values in table.items()
              if ("error" in column or "difference" in column) and
              "rate" not in column and "relative" not in column}
    for column, error in errors.items():
        axes[0, 0].loglog(step, error, "o-", label=column)
        if with_time:
            axes[0, 1].loglog(np.array(table["wall time [s]"], dtype=float),
                              error, "o-", label=column)
    # Reference slopes through the first error's value on the finest level:
    # 2/3 is the rate the corner singularity of the paper's scene allows.
    # Each line ends where it leaves the range of the errors.
    anchor = next(iter(errors.values()))[-1] if errors else 1.0
    top = 2 * max((e.max() for e in errors.values()), default=1.0)
    for slope, style in ((2 / 3, "k-."), (1, "k--"), (2, "k:")):
        end = min(step.max(), step.min() * (top / anchor) ** (1 / slope))
        axes[0, 0].loglog([step.min(), end],
                          [anchor, anchor * (end / step.min()) ** slope],
                          style, lw=0.8, label=f"slope {slope:.2g}")
    axes[0, 0].set_xlabel(step_name)
    axes[0, 0].set_ylabel("error")
    axes[0, 0].legend(fontsize=7)
    if with_time:
        axes[0, 1].set_xlabel("wall time of the level [s]")
        axes[0, 1].legend(fontsize=7)
    figure.savefig(os.path.join(output, "convergence.png"), dpi=DPI)
    plt.close(figure)
    return (f"{len(step)} levels against {step_name}; "
            + ", ".join(errors))


def main():
    parser = argparse.ArgumentParser(
        description=__doc__.split("\n\n")[0],
        formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("directory", help="the run's Output directory")
    parser.add_argument("--field", default="cell_von_mises",
                        help="VTU field that colours the deformed body "
                        "(vectors by their length)")
    parser.add_argument("--times", help="comma-separated times "
                        "(default: the run's Report times)")
    parser.add_argument("--coordinate", choices=("x", "y", "z", "angle"),
                        help="coordinate along Gamma_3 (default: the angle "
                        "about the z-axis where Gamma_3 is a circle or a "
                        "cylinder about it, else the coordinate in which "
                        "Gamma_3 extends furthest)")
    parser.add_argument("--output", help="directory for the PNG files "
                        "(default: <directory>/figures)")
    arguments = parser.parse_args()
    directory = arguments.directory
    if not os.path.isdir(directory):
        sys.exit(f"plot_run.py: no directory '{directory}'")
    output = arguments.output or os.path.join(directory, "figures")
    os.makedirs(output, exist_ok=True)

    written, skipped = [], []

    def record(name, shown, reason=None):
        (skipped if reason else written).append((name, reason or shown))

    convergence = os.path.join(directory, "convergence.txt")
    if os.path.exists(convergence):
        # A study's directory holds the table; each level is a run of its
        # own in level-<l>/, which this script draws when given it.
        record("convergence.png", plot_convergence(convergence, output))
        for name, _ in written:
            print(f"wrote {os.path.join(output, name)}: {_}")
        print("the levels' runs are in "
              f"{os.path.join(directory, 'level-0')}, ...: plot each of them")
        return

    outputs = ("time_series.csv", "solution.pvd", "gamma3_history.csv")
    if not any(os.path.exists(os.path.join(directory, name))
               for name in outputs):
        sys.exit(f"plot_run.py: '{directory}' holds no output of contact "
                 f"(none of {', '.join(outputs)}, convergence.txt)")
    series_path = os.path.join(directory, "time_series.csv")
    series = read_csv(series_path) if os.path.exists(series_path) else None
    if series is not None and len(series.get("time", [])) < 2:
        print(f"note: {series_path} has no step yet; it is not drawn")
        series = None
    end_time = float(read_parameter(directory, "End time") or "nan")
    records = read_pvd(directory)
    last_time = (series["time"][-1] if series is not None and
                 len(series["time"]) else
                 records[-1][0] if records else end_time)
    if not np.isfinite(end_time):
        end_time = last_time
    times = chosen_times(arguments, directory, last_time, end_time)

    shown, reason = plot_deformed(directory, times, arguments.field, output)
    record("deformed.png", shown, reason)
    shown, reason = plot_mesh(directory, times, output)
    record("mesh.png", shown, reason)
    history_path = os.path.join(directory, "gamma3_history.csv")
    history = read_csv(history_path) if os.path.exists(history_path) else None
    if history is None:
        reason = "no gamma3_history.csv (Output/Gamma3 history = false?)"
    elif len(history.get("step", [])) == 0:
        reason = "Gamma_3 has no nodes (Contact boundary ids empty?)"
    else:
        reason = None
        add_angle(history)
        coordinate = gamma3_coordinate(history, arguments.coordinate)
        record("gamma3_profiles.png",
               plot_gamma3_profiles(history, times, coordinate, output))
        record("stick_slip.png", plot_stick_slip(history, coordinate, output))
    if reason:
        record("gamma3_profiles.png", None, reason)
        record("stick_slip.png", None, reason)
    if series is not None:
        record("energies.png", plot_energies(series, output))
    else:
        record("energies.png", None, "no time_series.csv")
    for name, shown in written:
        print(f"wrote {os.path.join(output, name)}: {shown}")
    for name, reason in skipped:
        print(f"skipped {name}: {reason}")
    if not written:
        sys.exit("plot_run.py: no figure drawn (see the reasons above)")


if __name__ == "__main__":
    main()
