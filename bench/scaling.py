#!/usr/bin/env python3
"""Strong scaling of the big 3D scene: builds the program in
Release and runs prm/barboteu2015_3d_1m.prm (1.1 million unknowns, CG with
algebraic multigrid, 10 time steps) on 1 and 2 MPI processes, and the same
scene once coarser (h = 1/56) on 2 processes, to see how the linear
iterations grow when the mesh is refined once.

    python3 bench/scaling.py [--out bench/scaling.md]

Printed for every run: unknowns, steps, wall time, time per step, linear
(CG) iterations per step, the peak memory of the largest process; then the
1 -> 2 process speed-up of the time steps and of the whole run. Everything
is measured in this run; the table goes to --out as Markdown.
"""
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from run import ROOT, mpi_launcher, number, run, start  # noqa: E402


def run_scene(contact, processes, sets, directory):
    prm = os.path.join(ROOT, "prm", "barboteu2015_3d_1m.prm")
    output, wall, _ = run(mpi_launcher(processes) + [contact], prm, sets + [
        "Output/VTU interval=0", "Output/Progress interval=0",
        "Output/Print timings=true", f"Output/Output directory={directory}"])
    return {
        "unknowns": number(r"Q1, (\d+) unknowns", output),
        "steps": number(r"Done: (\d+) steps", output),
        "wall": wall,
        "time steps": number(r"\| Time steps +\| +\d+ \| +([0-9.e+-]+)s", output),
        "per step": number(r"Time per step ([0-9.e+-]+) ms", output),
        "iterations": number(r"CG-AMG, ([0-9.e+-]+) iterations per step", output),
        "memory": number(r"Peak memory per process: ([0-9.e+-]+) MB", output),
    }


def main():
    contact, out, lines = start("scaling.md", [
        "scene", "processes", "unknowns", "steps",
        "wall [s]", "time steps [s]", "per step [s]", "CG iterations/step",
        "peak memory/process [MB]"])
    coarse = ["Geometry/Cell size=0.017857142857142856",
              "Time/Time step=0.017857142857142856",
              "Time/End time=0.17857142857142858"]
    results = {}
    with tempfile.TemporaryDirectory() as tmp:
        for name, processes, sets in [("h = 1/56", 2, coarse),
                                      ("h = 1/112", 2, []),
                                      ("h = 1/112", 1, [])]:
            r = run_scene(contact, processes, sets, f"{tmp}/{name[-3:]}-{processes}")
            results[(name, processes)] = r
            line = (f"| {name} | {processes} | {r['unknowns']:.0f} | {r['steps']:.0f} "
                    f"| {r['wall']:.1f} | {r['time steps']:.1f} | {r['per step'] / 1e3:.2f} "
                    f"| {r['iterations']:.1f} | {r['memory']:.0f} |")
            lines.append(line)
            print(line, flush=True)

    one, two = results[("h = 1/112", 1)], results[("h = 1/112", 2)]
    coarse_run = results[("h = 1/56", 2)]
    summary = [
        "",
        f"Strong scaling 1 -> 2 processes at h = 1/112: time steps "
        f"{one['time steps'] / two['time steps']:.2f} times faster, whole run "
        f"{one['wall'] / two['wall']:.2f} times faster.",
        f"Refining once (h = 1/56 -> 1/112, {coarse_run['unknowns']:.0f} -> "
        f"{two['unknowns']:.0f} unknowns): CG iterations per step "
        f"{coarse_run['iterations']:.1f} -> {two['iterations']:.1f} "
        f"(x{two['iterations'] / coarse_run['iterations']:.2f}).",
    ]
    lines += summary
    print("\n".join(summary))
    with open(out, "w") as file:
        file.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
