#!/usr/bin/env python3
"""Work-precision study on the manufactured solution (exact errors):
error against wall time for element degree, h and k, the convexification
tolerance and Anderson acceleration.

Each setting is one convergence study of prm/manufactured_slip_front.prm
(the program's own 'Convergence study' mode); this script runs them one
after the other, collects convergence.txt, prints one Markdown table and
writes a PNG when matplotlib is there (Debian: python3-matplotlib, run
with /usr/bin/python3).

Usage: doc/work_precision.py path/to/contact prm/manufactured_slip_front.prm out.png
"""
import os
import platform
import subprocess
import sys
import tempfile

SETTINGS = [
    ("Q1, k = h", ["Geometry/Finite element degree=1", "Geometry/Cell size=0.125",
                   "Time/Time step=0.125", "Convergence study/Levels=4"]),
    ("Q2, k = h", ["Geometry/Finite element degree=2", "Geometry/Cell size=0.25",
                   "Time/Time step=0.25", "Convergence study/Levels=4"]),
    ("Q2, k = h/4", ["Geometry/Finite element degree=2", "Geometry/Cell size=0.25",
                     "Time/Time step=0.0625", "Convergence study/Levels=3"]),
    ("Q1, k = h, tolerance 1e-6", ["Geometry/Finite element degree=1",
                                   "Geometry/Cell size=0.125", "Time/Time step=0.125",
                                   "Convergence study/Levels=4",
                                   "Solver/Convexification tolerance=1e-6"]),
    ("Q1, k = h, plain convexification", ["Geometry/Finite element degree=1",
                                          "Geometry/Cell size=0.125",
                                          "Time/Time step=0.125",
                                          "Convergence study/Levels=4",
                                          "Solver/Anderson depth=0"]),
]


def read_org_table(path):
    rows = [[c.strip() for c in line.strip().strip("|").split("|")]
            for line in open(path) if line.startswith("|")]
    return [dict(zip(rows[0], row)) for row in rows[1:]]


def main():
    contact, prm, png = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2]), sys.argv[3]
    results = []
    with tempfile.TemporaryDirectory() as tmp:
        for name, entries in SETTINGS:
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
    print("| setting | h | k | unknowns | max V-error | max L2 velocity error | wall time [s] |")
    print("|---|---|---|---|---|---|---|")
    for name, rows in results:
        for row in rows:
            print(f"| {name} | {float(row['h']):.4g} | {float(row['k']):.4g} | {row['unknowns']} "
                  f"| {row['max V-error']} | {row['max L2 velocity error']} | {row['wall time [s]']} |")

    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return
    figure, axes = plt.subplots(1, 2, figsize=(11, 4.2), constrained_layout=True)
    for name, rows in results:
        time = [float(r["wall time [s]"]) for r in rows]
        axes[0].loglog(time, [float(r["max V-error"]) for r in rows], "o-", label=name)
        axes[1].loglog(time, [float(r["max L2 velocity error"]) for r in rows], "o-", label=name)
    for axis, title in zip(axes, ("max V-error ‖ε(u − u_h)‖", "max ‖w − w_h‖ in L2")):
        axis.set_xlabel("wall time of the run [s]")
        axis.set_ylabel("error")
        axis.set_title(title)
        axis.legend(fontsize=7)
    figure.savefig(png, dpi=110)


if __name__ == "__main__":
    main()
