#!/usr/bin/env python3
"""The two contact solver paths without CHOLMOD: builds the
program in Release and runs the same scenes with a Trilinos Amesos solver
(KLU on one process, MUMPS on two) on the Delassus path, whose D comes from
Z = K^{-1} C^T (one solve per tangential unknown of Gamma_3 at the start,
then one solve per step), and on the constraints path (one factorisation per
Newton step).

    python3 bench/paths.py [--out bench/paths.md]

Printed for every run: unknowns, tangential unknowns on Gamma_3, steps,
wall time, time per step, the time spent building D; then the ratio of the
two paths' times per step and wall times. Everything is measured in this
run; the table goes to --out as Markdown.
"""
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from run import ROOT, mpi_launcher, number, run, start  # noqa: E402

SCENES = [
    ("paper's scene, h = k = 1/64", "barboteu2015.prm",
     ["Geometry/Cell size=0.015625", "Time/Time step=0.015625"]),
    ("3D scene, h = k = 1/16", "barboteu2015_3d.prm",
     ["Geometry/Cell size=0.0625", "Time/Time step=0.0625"]),
]


def run_path(contact, scene, sets, processes, path, directory):
    solver = "Amesos_Klu" if processes == 1 else "Amesos_Mumps"
    output, wall, _ = run(mpi_launcher(processes) + [contact],
                          os.path.join(ROOT, "prm", scene), sets + [
        f"Solver/Linear solver={solver}", f"Solver/Contact solver={path}",
        "Output/VTU interval=0", "Output/Progress interval=0",
        "Output/Print timings=true", f"Output/Output directory={directory}"])
    delassus = 0.
    if path == "Delassus":
        delassus = number(r"\| Delassus operator +\| +\d+ \| +([0-9.e+-]+)s", output)
    return {
        "solver": solver,
        "unknowns": number(r", (\d+) unknowns", output),
        "gamma3": number(r"(\d+) free nodes on Gamma_3", output),
        "steps": number(r"Done: (\d+) steps", output),
        "wall": wall,
        "per step": number(r"Time per step ([0-9.e+-]+) ms", output),
        "delassus": delassus,
    }


def main():
    contact, out, lines = start("paths.md", [
        "scene", "processes", "solver", "path",
        "unknowns", "free nodes on Gamma_3", "steps", "wall [s]",
        "per step [ms]", "building D [s]"])
    ratios = []
    with tempfile.TemporaryDirectory() as tmp:
        for name, scene, sets in SCENES:
            for processes in (1, 2):
                r = {}
                for path in ("Delassus", "constraints"):
                    r[path] = run_path(contact, scene, sets, processes, path,
                                       f"{tmp}/{scene}-{processes}-{path}")
                    x = r[path]
                    line = (f"| {name} | {processes} | {x['solver']} | {path} "
                            f"| {x['unknowns']:.0f} | {x['gamma3']:.0f} | {x['steps']:.0f} "
                            f"| {x['wall']:.2f} | {x['per step']:.2f} | {x['delassus']:.2f} |")
                    lines.append(line)
                    print(line, flush=True)
                ratios.append(
                    f"{name}, {processes} process{'es' if processes > 1 else ''} "
                    f"({r['Delassus']['solver']}): the constraints path takes "
                    f"{r['constraints']['per step'] / r['Delassus']['per step']:.1f} times "
                    f"as long per step and {r['constraints']['wall'] / r['Delassus']['wall']:.1f} "
                    f"times as long in all as the Delassus path.")
    lines += [""] + ratios
    print("\n".join([""] + ratios))
    with open(out, "w") as file:
        file.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
