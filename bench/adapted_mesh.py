#!/usr/bin/env python3
"""Adapted meshes against uniform and hand-graded ones on the paper's scene
(prm/barboteu2015.prm): the V-error at T, ||eps(u_ref(T) - u_h(T))||,
against the number of unknowns and the wall time. Builds the program's
library and bench/adapted_mesh_error.cc in Release, runs the reference
(Q2, h = 1/256, k = T/564) and every mesh below with the scene's
k = T/141, and writes a Markdown table (--out) and, with matplotlib, a
plot next to it.

    python3 bench/adapted_mesh.py [--out bench/adapted_mesh.md]

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
from run import ROOT, build, machine  # noqa: E402

STEP = "Time/Time step=0.0078014184397163121"  # T / 141, the scene's k
COMMON = ["Output/VTU interval=0", "Output/Report times=",
          "Output/Print timings=false", "Output/Progress interval=0"]
REFERENCE = ["Geometry/Finite element degree=2", "Geometry/Cell size=0.00390625",
             "Time/Time step=0.0019503546099290780"]
GRADED = ["Geometry/Refinement points=0, 0.5", "Geometry/Refinement radius=0.25"]
ADAPTED = ["Geometry/Cell size=0.03125", "Mesh adaptation/Max levels=3"]

RUNS = [
    ("uniform, h = 1/32", ["Geometry/Cell size=0.03125"]),
    ("uniform, h = 1/64", ["Geometry/Cell size=0.015625"]),
    ("uniform, h = 1/128", ["Geometry/Cell size=0.0078125"]),
    ("graded, h = 1/32", ["Geometry/Cell size=0.03125"] + GRADED),
    ("graded, h = 1/64", ["Geometry/Cell size=0.015625"] + GRADED),
    ("adapted (Kelly of u, the default), 3 cycles to 2000 unknowns",
     ADAPTED + ["Mesh adaptation/Cycles=3", "Mesh adaptation/Target unknowns=2000"]),
    ("adapted (Kelly of u, the default), 3 cycles to 4000 unknowns",
     ADAPTED + ["Mesh adaptation/Cycles=3", "Mesh adaptation/Target unknowns=4000"]),
    ("adapted (Kelly of u, the default), 3 cycles to 8000 unknowns",
     ADAPTED + ["Mesh adaptation/Cycles=3", "Mesh adaptation/Target unknowns=8000"]),
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
] + [
    (f"during the run (Kelly of u), every 10 steps, 30 % refined and 10 % coarsened, "
     f"towards {target} unknowns",
     ADAPTED + ["Mesh adaptation/Interval=10", "Mesh adaptation/Coarsen fraction=0.1",
                f"Mesh adaptation/Target unknowns={target}"])
    for target in (2000, 4000, 8000)
]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--out", default=os.path.join(ROOT, "bench", "adapted_mesh.md"))
    out = parser.parse_args().out
    tool = build("adapted_mesh_error")
    with tempfile.TemporaryDirectory() as tmp:
        command = [tool, os.path.join(ROOT, "prm", "barboteu2015.prm")]
        command += REFERENCE + COMMON + [f"Output/Output directory={tmp}/reference"]
        for index, (_, sets) in enumerate(RUNS):
            command += ["--", STEP] + COMMON + sets + [
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
    if len(rows) != len(RUNS):
        sys.exit("adapted_mesh_error printed " + str(len(rows)) + " rows:\n" + output.stdout)

    uniform = rows[2]
    lines = [f"Machine: {machine()}", "",
             "prm/barboteu2015.prm (Q1, k = T/141), V-error at T = 1.1 against Q2 "
             "with h = 1/256, k = T/564. Produced by `python3 bench/adapted_mesh.py`.", "",
             "| mesh | unknowns (at T) | pilots [s] | run [s] | total [s] | V-error at T "
             "| unknowns / uniform 1/128 | total time / uniform 1/128 |",
             "|---|---|---|---|---|---|---|---|"]
    for (name, _), row in zip(RUNS, rows):
        total = row["pilots"] + row["wall"]
        lines.append(
            f"| {name} | {row['unknowns']:.0f} | {row['pilots']:.2f} | {row['wall']:.2f} "
            f"| {total:.2f} | {row['error']:.3e} | {row['unknowns'] / uniform['unknowns']:.3f} "
            f"| {total / (uniform['pilots'] + uniform['wall']):.3f} |")
    print("\n".join(lines))
    with open(out, "w") as file:
        file.write("\n".join(lines) + "\n")

    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return
    figure, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    for family, marker in (("uniform", "o-"), ("graded", "s-"), ("adapted", "^"),
                           ("during", "v")):
        chosen = [(row, name) for (name, _), row in zip(RUNS, rows) if name.startswith(family)]
        if not chosen:
            continue
        errors = [row["error"] for row, _ in chosen]
        label = {"adapted": "adapted by pilots",
                 "during": "adapted during the run (unknowns at T)"}.get(family, family)
        axes[0].loglog([row["unknowns"] for row, _ in chosen], errors, marker, label=label)
        axes[1].loglog([row["pilots"] + row["wall"] for row, _ in chosen], errors, marker,
                       label=label)
    axes[0].set_xlabel("unknowns")
    axes[1].set_xlabel("wall time, pilots included [s]")
    for axis in axes:
        axis.set_ylabel("V-error at T [m]")
        axis.grid(True, which="both", alpha=0.3)
        axis.legend()
    figure.tight_layout()
    figure.savefig(os.path.splitext(out)[0] + ".png", dpi=110)


if __name__ == "__main__":
    main()
