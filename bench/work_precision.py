#!/usr/bin/env python3
"""Work-precision studies: error against wall time for the element
(Q1, Q2 on quadrilaterals, P1, P2 on triangles), h and k, the
convexification tolerance, the active set parameter and Anderson
acceleration.

Each setting is one convergence study (the program's own 'Convergence
study' mode), run one after the other; the script collects their
convergence.txt, prints a Markdown table and writes a PNG when matplotlib
is there (Debian: python3-matplotlib, run with /usr/bin/python3).

  manufactured: prm/manufactured_slip_front.prm, exact errors (max V-error)
  paper:        prm/barboteu2015.prm, V-error at T against a Q2 reference
                at the finest level of each study

Usage: bench/work_precision.py path/to/contact manufactured|paper prm out.png
"""
import os
import platform
import subprocess
import sys
import tempfile

PAPER = [
    ("Q1, k = h", ["Geometry/Finite element degree=1"]),
    ("Q2, k = h", ["Geometry/Finite element degree=2"]),
    ("Q2, k = h/4", ["Geometry/Finite element degree=2", "Time/Time step=0.125"]),
    ("Q1, k = h, lumped mass", ["Geometry/Finite element degree=1", "Geometry/Mass matrix=lumped"]),
    ("Q1, k = h, graded", ["Geometry/Finite element degree=1",
                           "Geometry/Refinement points=0, 0.5",
                           "Geometry/Refinement radius=0.25"]),
    ("Q2, k = h, graded", ["Geometry/Finite element degree=2",
                           "Geometry/Refinement points=0, 0.5",
                           "Geometry/Refinement radius=0.25"]),
    ("P1 triangles, k = h", ["Geometry/Cell shape=simplex",
                             "Geometry/Finite element degree=1"]),
    ("P2 triangles, k = h", ["Geometry/Cell shape=simplex",
                             "Geometry/Finite element degree=2"]),
]
PAPER_COMMON = ["Geometry/Cell size=0.5", "Time/Time step=0.5", "Convergence study/Levels=6",
                "Convergence study/Reference degree=2", "Output/VTU interval=0",
                "Output/Report times="]

MANUFACTURED = [
    ("Q1, k = h", ["Geometry/Finite element degree=1", "Geometry/Cell size=0.125",
                   "Time/Time step=0.125", "Convergence study/Levels=4"]),
    ("Q2, k = h", ["Geometry/Finite element degree=2", "Geometry/Cell size=0.25",
                   "Time/Time step=0.25", "Convergence study/Levels=4"]),
    ("Q2, k = h/4", ["Geometry/Finite element degree=2", "Geometry/Cell size=0.25",
                     "Time/Time step=0.0625", "Convergence study/Levels=3"]),
    ("P1 triangles, k = h", ["Geometry/Cell shape=simplex", "Geometry/Finite element degree=1",
                             "Geometry/Cell size=0.125", "Time/Time step=0.125",
                             "Convergence study/Levels=4"]),
    ("P2 triangles, k = h/4", ["Geometry/Cell shape=simplex", "Geometry/Finite element degree=2",
                               "Geometry/Cell size=0.25", "Time/Time step=0.0625",
                               "Convergence study/Levels=3"]),
    ("Q1, k = h, lumped mass", ["Geometry/Finite element degree=1", "Geometry/Cell size=0.125",
                                "Time/Time step=0.125", "Convergence study/Levels=4",
                                "Geometry/Mass matrix=lumped"]),
    ("Q1, k = h, tolerance 1e-6", ["Geometry/Finite element degree=1",
                                   "Geometry/Cell size=0.125", "Time/Time step=0.125",
                                   "Convergence study/Levels=4",
                                   "Solver/Friction method=convexification",
                                   "Solver/Convexification tolerance=1e-6"]),
    ("Q1, k = h, active set parameter 1", ["Geometry/Finite element degree=1",
                                           "Geometry/Cell size=0.125",
                                           "Time/Time step=0.125",
                                           "Convergence study/Levels=4",
                                           "Solver/Active set parameter=1"]),
    ("Q1, k = h, plain convexification", ["Geometry/Finite element degree=1",
                                          "Geometry/Cell size=0.125",
                                          "Time/Time step=0.125",
                                          "Convergence study/Levels=4",
                                          "Solver/Friction method=convexification",
                                          "Solver/Anderson depth=0"]),
]


def read_org_table(path):
    rows = [[c.strip() for c in line.strip().strip("|").split("|")]
            for line in open(path) if line.startswith("|")]
    return [dict(zip(rows[0], row)) for row in rows[1:]]


def main():
    contact, study = os.path.abspath(sys.argv[1]), sys.argv[2]
    prm, png = os.path.abspath(sys.argv[3]), sys.argv[4]
    if study == "paper":
        settings = [(name, PAPER_COMMON + entries) for name, entries in PAPER]
        columns = ("V-error at T", "V-difference to next level at T")
    else:
        settings = MANUFACTURED
        columns = ("max V-error", "max L2 velocity error")
    results = []
    with tempfile.TemporaryDirectory() as tmp:
        for name, entries in settings:
            directory = os.path.join(tmp, str(len(results)))
            command = [contact]
            for entry in entries + ["Output/Output directory=" + directory,
                                    "Output/Print timings=true"]:
                command += ["--set", entry]
            subprocess.run(command + [prm], check=True, capture_output=True)
            results.append((name, read_org_table(os.path.join(directory, "convergence.txt"))))

    print(f"Machine: {platform.machine()}, {os.cpu_count()} cores, "
          f"{platform.processor() or platform.platform()}")
    print()
    print(f"| setting | h | k | unknowns | {columns[0]} | {columns[1]} | wall time [s] |")
    print("|---|---|---|---|---|---|---|")
    for name, rows in results:
        for row in rows:
            print(f"| {name} | {float(row['h']):.4g} | {float(row['k']):.4g} | {row['unknowns']} "
                  f"| {row[columns[0]]} | {row[columns[1]]} | {row['wall time [s]']} |")

    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return
    figure, axes = plt.subplots(1, 2, figsize=(11, 4.2), constrained_layout=True)
    for name, rows in results:
        time = [float(r["wall time [s]"]) for r in rows]
        axes[0].loglog(time, [float(r[columns[0]]) for r in rows], "o-", label=name)
        axes[1].loglog(time, [float(r[columns[1]]) for r in rows], "o-", label=name)
    for axis, title in zip(axes, columns):
        axis.set_xlabel("wall time of the run [s]")
        axis.set_ylabel("error")
        axis.set_title(title)
        axis.legend(fontsize=7)
    figure.savefig(png, dpi=110)


if __name__ == "__main__":
    main()
