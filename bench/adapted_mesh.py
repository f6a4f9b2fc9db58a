#!/usr/bin/env python3
"""Adapted meshes against uniform and hand-graded ones on the paper's scene
(prm/barboteu2015.prm, Q1 and Q2; with --scene 3d the 3D scene,
prm/barboteu2015_3d.prm, and with --scene bushing the bushing on a curved
Γ3, prm/bushing.prm, Q1 and Q2, against uniform meshes): the V-error at
T, ||eps(u_ref(T) - u_h(T))||,
against the number of unknowns and the wall time. Builds the program and
bench/adapted_mesh_error.cc in Release, runs the reference (2D: Q2 from
h = 1/256 adapted during the run towards the corner, at the runs' k =
T/141, so that the difference is the error of the mesh) and every mesh
below, and writes a Markdown table (--out) and, with matplotlib, a plot
next to it. The reference runs once more with the program's own error
estimate, split into space and time ('Accuracy/Separate space and time'):
its space part, printed under the table, says how far the reference
itself is from the exact solution at that k.

    python3 bench/adapted_mesh.py [--scene 2d|3d|bushing] [--out FILE]

Adapted meshes start from h = 1/32 and refine towards a number of
unknowns (or 30 % of the cells per cycle), at most 3 levels (h >= 1/256,
so that the reference's space holds every mesh's), with the default
indicator (Kelly's of u) or others; the runs adapted during themselves
('Mesh adaptation/Interval') start from the same mesh, and their unknowns
are those of the last mesh. The wall time of a pilot-adapted run is the
pilots' and the run's; the others have no pilots. Every number is
measured in this run.
"""
import argparse
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from run import ROOT, build, machine, own_estimate  # noqa: E402

STEP = "Time/Time step=0.0078014184397163121"  # T / 141, the scene's k
COMMON = ["Output/VTU interval=0", "Output/Report times=",
          "Output/Print timings=false", "Output/Progress interval=0"]
# The reference: Q2 at the runs' k, so that the difference is the error of
# the mesh, from h = 1/256 (every mesh below lies in its space) adapted
# during the run by up to 3 levels more towards the corner (0, 0.5), where
# a uniform mesh converges at about h^(2/3) only.
REFERENCE = ["Geometry/Finite element degree=2", "Geometry/Cell size=0.00390625",
             STEP, "Mesh adaptation/Interval=10", "Mesh adaptation/Coarsen fraction=0.1",
             "Mesh adaptation/Max levels=3", "Mesh adaptation/Target unknowns=600000"]
GRADED = ["Geometry/Refinement points=0, 0.5", "Geometry/Refinement radius=0.25"]
ADAPTED = ["Geometry/Cell size=0.03125", "Mesh adaptation/Max levels=3"]
Q2 = ["Geometry/Finite element degree=2"]
ADAPTED_Q2 = Q2 + ["Geometry/Cell size=0.0625", "Mesh adaptation/Max levels=3"]


def adapted_by_pilots(label, base, cycles, targets):
    """Runs on meshes adapted by `cycles` pilots towards each target."""
    return [(f"adapted{label}, {cycles} cycles to {target} unknowns",
             base + [f"Mesh adaptation/Cycles={cycles}",
                     f"Mesh adaptation/Target unknowns={target}"]) for target in targets]


def adapted_during_run(label, base, interval, targets):
    """Runs adapted after every `interval`-th step towards each target."""
    return [(f"during the run{label}, every {interval} steps, 30 % refined and 10 % "
             f"coarsened, towards {target} unknowns",
             base + [f"Mesh adaptation/Interval={interval}",
                     "Mesh adaptation/Coarsen fraction=0.1",
                     f"Mesh adaptation/Target unknowns={target}"]) for target in targets]


RUNS = [
    ("uniform, h = 1/32", ["Geometry/Cell size=0.03125"]),
    ("uniform, h = 1/64", ["Geometry/Cell size=0.015625"]),
    ("uniform, h = 1/128", ["Geometry/Cell size=0.0078125"]),
    ("graded, h = 1/32", ["Geometry/Cell size=0.03125"] + GRADED),
    ("graded, h = 1/64", ["Geometry/Cell size=0.015625"] + GRADED),
] + adapted_by_pilots(" (Kelly of u, the default)", ADAPTED, 3, (2000, 4000, 8000)) + [
    ("adapted (Kelly of u, the default), 30 % per cycle, 3 cycles",
     ADAPTED + ["Mesh adaptation/Cycles=3"]),
    ("adapted (Kelly of u and w), 3 cycles to 2000 unknowns",
     ADAPTED + ["Mesh adaptation/Cycles=3", "Mesh adaptation/Target unknowns=2000",
                "Mesh adaptation/Indicators=displacement, velocity"]),
    ("adapted (Kelly of u and w), 3 cycles to 4000 unknowns",
     ADAPTED + ["Mesh adaptation/Cycles=3", "Mesh adaptation/Target unknowns=4000",
                "Mesh adaptation/Indicators=displacement, velocity"]),
    ("adapted (all three), 3 cycles to 2000 unknowns",
     ADAPTED + ["Mesh adaptation/Cycles=3", "Mesh adaptation/Target unknowns=2000",
                "Mesh adaptation/Indicators=displacement, velocity, slip rate"]),
    ("adapted (all three), 3 cycles to 4000 unknowns",
     ADAPTED + ["Mesh adaptation/Cycles=3", "Mesh adaptation/Target unknowns=4000",
                "Mesh adaptation/Indicators=displacement, velocity, slip rate"]),
] + adapted_during_run(" (Kelly of u)", ADAPTED, 10, (2000, 4000, 8000)) + [
    # Q2 from h = 1/16: at most three levels, so that h >= 1/128 lies in the
    # reference's space.
    ("uniform Q2, h = 1/16", Q2 + ["Geometry/Cell size=0.0625"]),
    ("uniform Q2, h = 1/32", Q2 + ["Geometry/Cell size=0.03125"]),
    ("uniform Q2, h = 1/64", Q2 + ["Geometry/Cell size=0.015625"]),
    ("graded Q2, h = 1/16", Q2 + ["Geometry/Cell size=0.0625"] + GRADED),
    ("graded Q2, h = 1/32", Q2 + ["Geometry/Cell size=0.03125"] + GRADED),
] + adapted_by_pilots(" Q2 (Kelly of u)", ADAPTED_Q2, 3, (2000, 4000)) + \
    adapted_during_run(" Q2 (Kelly of u)", ADAPTED_Q2, 10, (2000, 4000)) + \
    adapted_during_run(" Q2 (Kelly of u)", ADAPTED_Q2, 20, (1500,))


# The 3D scene (prm/barboteu2015_3d.prm, k = T/18): Q1 and Q2 from h = 1/8,
# at most one level finer (h >= 1/16), against Q2 with h = 1/16 and
# k = T/72.
STEP_3D = "Time/Time step=0.061111111111111116"  # T / 18, the scene's k
REFERENCE_3D = ["Geometry/Finite element degree=2", "Geometry/Cell size=0.0625",
                "Time/Time step=0.015277777777777779"]
ADAPTED_3D = ["Geometry/Cell size=0.125", "Mesh adaptation/Max levels=1"]
RUNS_3D = [
    ("uniform, h = 1/8", ["Geometry/Cell size=0.125"]),
    ("uniform, h = 1/16", ["Geometry/Cell size=0.0625"]),
] + adapted_by_pilots(" (Kelly of u, the default)", ADAPTED_3D, 2, (1500, 2500)) + \
    adapted_during_run(" (Kelly of u)", ADAPTED_3D, 3, (1500, 2500)) + [
    # Q2 from h = 1/8, at most one level finer: in the reference's space.
    ("uniform Q2, h = 1/8", Q2 + ["Geometry/Cell size=0.125"]),
] + adapted_by_pilots(" Q2 (Kelly of u)", Q2 + ADAPTED_3D, 2, (8000, 12000)) + \
    adapted_during_run(" Q2 (Kelly of u)", Q2 + ADAPTED_3D, 3, (8000, 12000))

# The bushing (prm/bushing.prm, Q2 on a curved mesh): uniform Q1 and Q2
# meshes of 8 x 4^r cells, and Q2 adapted from r = 1 by at most three
# levels (r <= 4), against Q2 with r = 5, all at the reference's k = T/512:
# at the scene's k = T/128 the time error (first order in k) hides the
# space error of Q2 from 512 cells on (9.4e-4 on 512 and 9.3e-4 on 2048
# cells), so the meshes are compared at equal k.
STEP_BUSHING = "Time/Time step=0.00390625"  # T / 512
REFERENCE_BUSHING = ["Geometry/Mesh refinements=5", "Time/Time step=0.00390625"]
ADAPTED_BUSHING = ["Geometry/Mesh refinements=1", "Mesh adaptation/Max levels=3"]
Q1 = ["Geometry/Finite element degree=1"]
RUNS_BUSHING = [
    (f"uniform Q1, {8 * 4**r} cells", Q1 + [f"Geometry/Mesh refinements={r}"])
    for r in (2, 3, 4)
] + [
    (f"uniform Q2, {8 * 4**r} cells", [f"Geometry/Mesh refinements={r}"])
    for r in (1, 2, 3, 4)
] + adapted_by_pilots(" Q2 (Kelly of u)", ADAPTED_BUSHING, 3, (1000, 2000, 4000)) + \
    adapted_during_run(" Q2 (Kelly of u)", ADAPTED_BUSHING, 32, (1000, 2000, 4000))

SCENES = {
    "2d": ("barboteu2015.prm", STEP, REFERENCE, RUNS, 2,
           "prm/barboteu2015.prm (Q1 and Q2, k = T/141), V-error at T = 1.1 against Q2 at "
           "the same k from h = 1/256, adapted during the run by up to three levels more: "
           "the error of the mesh."),
    "3d": ("barboteu2015_3d.prm", STEP_3D, REFERENCE_3D, RUNS_3D, 1,
           "prm/barboteu2015_3d.prm (Q1, k = T/18), V-error at T = 1.1 against Q2 with "
           "h = 1/16, k = T/72."),
    "bushing": ("bushing.prm", STEP_BUSHING, REFERENCE_BUSHING, RUNS_BUSHING, 6,
                "prm/bushing.prm (k = T/512), V-error at T = 2 against Q2 with 8192 cells "
                "and the same k: the error of the mesh alone."),
}


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--scene", choices=sorted(SCENES), default="2d")
    parser.add_argument("--out")
    parser.add_argument("--replot", action="store_true",
                        help="draw the plot of the table in --out again, without running")
    arguments = parser.parse_args()
    scene, STEP_, REFERENCE_, RUNS_, uniform_index, title = SCENES[arguments.scene]
    out = arguments.out or os.path.join(
        ROOT, "bench", "adapted_mesh.md" if arguments.scene == "2d" else
        f"adapted_mesh_{arguments.scene}.md")
    if arguments.replot:
        plot(*read_table(out), out)
        return
    tool, contact = build("adapted_mesh_error"), build()
    with tempfile.TemporaryDirectory() as tmp:
        estimate, estimate_unknowns = own_estimate(
            contact, os.path.join(ROOT, "prm", scene),
            REFERENCE_ + COMMON + [f"Output/Output directory={tmp}/estimate"], True)
        command = [tool, os.path.join(ROOT, "prm", scene)]
        command += REFERENCE_ + COMMON + [f"Output/Output directory={tmp}/reference"]
        for index, (_, sets) in enumerate(RUNS_):
            command += ["--", STEP_] + COMMON + sets + [
                f"Output/Output directory={tmp}/run-{index}"]
        output = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                text=True, cwd=tmp)
        if output.returncode != 0:
            sys.exit("adapted_mesh_error failed:\n" + output.stdout)
    rows = []
    for line in output.stdout.splitlines():
        words = line.split()
        if words and words[0] == "unknowns":
            values = dict(zip(words[0::2], words[1::2]))
            rows.append({k: float(v) for k, v in values.items()})
    if len(rows) != len(RUNS_):
        sys.exit("adapted_mesh_error printed " + str(len(rows)) + " rows:\n" + output.stdout)

    uniform = rows[uniform_index]
    finest = RUNS_[uniform_index][0].split(", ")[-1].replace("h = ", "")
    lines = [f"Machine: {machine()}", "",
             f"{title} Produced by `python3 bench/adapted_mesh.py --scene "
             f"{arguments.scene}`.", "",
             "| mesh | unknowns (at T) | pilots [s] | run [s] | total [s] | V-error at T "
             f"| unknowns / uniform {finest} | total time / uniform {finest} |",
             "|---|---|---|---|---|---|---|---|"]
    for (name, _), row in zip(RUNS_, rows):
        total = row["pilots"] + row["wall"]
        lines.append(
            f"| {name} | {row['unknowns']:.0f} | {row['pilots']:.2f} | {row['wall']:.2f} "
            f"| {total:.2f} | {row['error']:.3e} | {row['unknowns'] / uniform['unknowns']:.3f} "
            f"| {total / (uniform['pilots'] + uniform['wall']):.3f} |")
    lines += ["", f"The reference: {estimate_unknowns} unknowns at T; the program's own "
              f"estimate of its V-error at T: space part {estimate['space part']}, time "
              f"part {estimate['time part']}, together {estimate['estimated error']} "
              f"({estimate['status']}; orders {estimate['order used']})."]
    print("\n".join(lines))
    with open(out, "w") as file:
        file.write("\n".join(lines) + "\n")

    plot([name for name, _ in RUNS_], rows, out)


def plot(names, rows, out):
    """The V-error against unknowns and against wall time, per family of
    meshes, next to the table (out with .png)."""
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("no matplotlib: no plot (run with /usr/bin/python3)")
        return
    figure, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    markers = {("uniform", "Q1"): "o-", ("graded", "Q1"): "s-", ("adapted", "Q1"): "^",
               ("during", "Q1"): "v", ("uniform", "Q2"): "o--", ("graded", "Q2"): "s--",
               ("adapted", "Q2"): "D", ("during", "Q2"): "x"}
    for (family, degree), marker in markers.items():
        # A name without a degree is of Q1 (the paper's scenes).
        chosen = [row for name, row in zip(names, rows) if name.startswith(family)
                  and (degree in name or (degree == "Q1" and "Q2" not in name))]
        if not chosen:
            continue
        errors = [row["error"] for row in chosen]
        label = {"adapted": "adapted by pilots",
                 "during": "adapted during the run (unknowns at T)"}.get(family, family)
        label += ", " + degree
        axes[0].loglog([row["unknowns"] for row in chosen], errors, marker, label=label)
        axes[1].loglog([row["pilots"] + row["wall"] for row in chosen], errors, marker,
                       label=label)
    axes[0].set_xlabel("unknowns")
    axes[1].set_xlabel("wall time, pilots included [s]")
    for axis in axes:
        axis.set_ylabel("V-error at T [m]")
        axis.grid(True, which="both", alpha=0.3)
        axis.legend(fontsize=7, loc="lower left")
    figure.tight_layout()
    figure.savefig(os.path.splitext(out)[0] + ".png", dpi=110)


def read_table(path):
    """The names and rows of a table this script wrote (for --replot)."""
    names, rows = [], []
    for line in open(path):
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) == 8 and cells[1].replace(".", "").isdigit():
            names.append(cells[0])
            rows.append({"unknowns": float(cells[1]), "pilots": float(cells[2]),
                         "wall": float(cells[3]), "error": float(cells[5])})
    return names, rows


if __name__ == "__main__":
    main()
