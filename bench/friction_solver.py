#!/usr/bin/env python3
"""The friction solve on Gamma_3: builds the program in Release and runs the
2D default scene and the 3D scene (prm/barboteu2015_3d.prm at h = k =
1/16 and 1/32) on the Delassus path, and the 3D scene at 1/16 on the
constraints path with the direct solver and with CG-AMG, each with the
default friction method (no 'Solver/Friction method' set: Newton) and
with 'Solver/Friction method = convexification', and the Delassus runs
once more with the reference BLAS/LAPACK instead of the optimised one.

    python3 bench/friction_solver.py [--out bench/friction_solver.md]

Printed for every run: unknowns, free nodes on Gamma_3, steps, Newton and
convexification iterations per step, the steps that ended beyond the
convexity limit and those the convexification took over (Newton's summary
line), active set iterations per step, solves with K per step, CG iterations
per step, time per step, its ratio to one substitution with the factor of K
(or solve with K), wall time and peak memory. Every run is repeated REPEATS
times in a row: the counts must agree; times and peak memory are the medians
of the repeats (the ratio also with its smallest and largest value).
Everything is measured in this run; the table goes to --out as Markdown.
"""
import os
import re
import statistics
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from run import ROOT, number, run, start  # noqa: E402

SCENES = [
    ("2D default, h = k = 1/128", "barboteu2015.prm", [], "Delassus"),
    ("3D, h = k = 1/16", "barboteu2015_3d.prm", [], "Delassus"),
    ("3D, h = k = 1/32", "barboteu2015_3d.prm",
     ["Geometry/Cell size=0.03125", "Time/Time step=0.03125"], "Delassus"),
    ("3D, h = k = 1/16", "barboteu2015_3d.prm", [], "constraints"),
    ("3D, h = k = 1/16, CG-AMG", "barboteu2015_3d.prm",
     ["Solver/Linear solver=CG-AMG"], "constraints"),
]

# Runs of each configuration; the times printed are their median.
REPEATS = 3

# The program's default (nothing set) and the paper's method.
METHODS = (("default (Newton)", []),
           ("convexification", ["Solver/Friction method=convexification"]))

# Debian's reference BLAS/LAPACK, which the generic libblas.so.3 resolves to
# without an optimised implementation.
REFERENCE_BLAS = ("/usr/lib/x86_64-linux-gnu/blas:"
                  "/usr/lib/x86_64-linux-gnu/lapack")


def blas_in_use():
    try:
        return os.path.realpath("/etc/alternatives/libblas.so.3-x86_64-linux-gnu")
    except OSError:
        return "unknown"


def optional(pattern, text, default=0.):
    match = re.search(pattern, text)
    return float(match.group(1)) if match else default


def run_scene(contact, scene, sets, path, method_sets, directory, reference_blas):
    saved = os.environ.get("LD_LIBRARY_PATH")
    if reference_blas:
        os.environ["LD_LIBRARY_PATH"] = REFERENCE_BLAS
    try:
        output, wall, memory = run(contact, os.path.join(ROOT, "prm", scene), sets + method_sets + [
            f"Solver/Contact solver={path}",
            "Output/VTU interval=0", "Output/Progress interval=0",
            "Output/Print timings=true", f"Output/Output directory={directory}"])
    finally:
        if saved is None:
            os.environ.pop("LD_LIBRARY_PATH", None)
        else:
            os.environ["LD_LIBRARY_PATH"] = saved
    steps = number(r"Done: (\d+) steps", output)
    return {
        "unknowns": number(r", (\d+) unknowns", output),
        "gamma3": number(r"(\d+) free nodes on Gamma_3", output),
        "steps": steps,
        "newton": optional(r"Newton on the full friction law: (\d+) iterations",
                           output) / steps,
        "beyond": optional(r"(\d+) steps ended beyond the convexity limit", output),
        "taken over": optional(r"the convexification took over in (\d+) steps", output),
        "convexification": number(r"(\d+) convexification iterations", output) / steps,
        "active set": number(r"(\d+) active set iterations", output) / steps,
        "solves": number(r"Solves with K per step: ([0-9.e+-]+)", output),
        "cg": optional(r"CG iterations per step: ([0-9.e+-]+)", output),
        "per step": number(r"Time per step ([0-9.e+-]+) ms", output),
        "ratio": number(r"ms = ([0-9.e+-]+) (?:substitutions|solves)", output),
        "wall": wall,
        "memory": memory,
    }


def repeated(*arguments):
    """run_scene REPEATS times: the counts of the first run (all must give
    the same), the median of the times, the ratio's range."""
    runs = [run_scene(*arguments) for _ in range(REPEATS)]
    timed = ("per step", "ratio", "wall", "memory")
    for x in runs[1:]:
        for key, value in x.items():
            if key not in timed and value != runs[0][key]:
                sys.exit(f"{arguments[1]} {arguments[2]} on the {arguments[3]} path "
                         f"with {arguments[4] or 'the default method'}: the repeats "
                         f"differ in '{key}': {value} against {runs[0][key]}")
    result = dict(runs[0])
    for key in timed:
        result[key] = statistics.median(x[key] for x in runs)
    result["ratio range"] = (min(x["ratio"] for x in runs), max(x["ratio"] for x in runs))
    return result


def main():
    contact, out, lines = start("friction_solver.md", [
        "scene", "path", "BLAS", "friction method", "unknowns",
        "free nodes on Gamma_3", "steps", "Newton it./step",
        "steps beyond the convexity limit", "steps taken over",
        "convexification it./step", "active set it./step",
        "solves with K/step", "CG it./step", "per step [ms]",
        "step / substitution (or solve): median (range)", "wall [s]", "peak memory [MB]"])
    lines.insert(1, f"BLAS: {blas_in_use()} (reference: {REFERENCE_BLAS})")
    print(lines[1])
    notes = []
    with tempfile.TemporaryDirectory() as tmp:
        for name, scene, sets, path in SCENES:
            blas_choices = (False, True) if path == "Delassus" else (False,)
            for reference_blas in blas_choices:
                r = {}
                for method, method_sets in METHODS:
                    x = r[method] = repeated(
                        contact, scene, sets, path, method_sets,
                        f"{tmp}/{len(lines)}", reference_blas)
                    low, high = x["ratio range"]
                    line = (f"| {name} | {path} | {'reference' if reference_blas else 'optimised'} "
                            f"| {method} | {x['unknowns']:.0f} | {x['gamma3']:.0f} "
                            f"| {x['steps']:.0f} | {x['newton']:.2f} "
                            f"| {x['beyond']:.0f} | {x['taken over']:.0f} "
                            f"| {x['convexification']:.1f} | {x['active set']:.1f} "
                            f"| {x['solves']:.1f} | {x['cg']:.0f} | {x['per step']:.1f} "
                            f"| {x['ratio']:.2f} ({low:.2f} to {high:.2f}) "
                            f"| {x['wall']:.2f} | {x['memory']:.0f} |")
                    lines.append(line)
                    print(line, flush=True)
                notes.append(
                    f"{name}, {path}, {'reference' if reference_blas else 'optimised'} "
                    f"BLAS: the default (Newton) takes "
                    f"{r[METHODS[0][0]]['per step'] / r['convexification']['per step']:.2f} "
                    f"times the time per step of the convexification.")
    lines += [""] + notes
    print("\n".join([""] + notes))
    with open(out, "w") as file:
        file.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
