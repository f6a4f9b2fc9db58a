#!/usr/bin/env python3
"""Where 'Contact solver = auto' should leave the Delassus path, with the
default linear solver on one process (CHOLMOD): builds the program in
Release and runs prm/barboteu2015_3d.prm to t = 0.5 (slip from t = 0.33 on)
at h = k = 1/32, 1/48 and 1/64 on both paths, each to the end or to a
limit of --limit seconds (a run that reaches it is reported as stopped,
with the steps it finished).

    python3 bench/auto_path.py [--out bench/auto_path.md] [--limit 900]

Printed for every run: unknowns, tangential unknowns on Gamma_3, steps
finished, wall time, the time spent building D and factorising K, the
Newton iterations and solves with K in the slipping steps; then the ratio of
the two paths' wall times where both finished. Everything is measured in
this run; the table goes to --out as Markdown.
"""
import argparse
import csv
import os
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from run import ROOT, build, table_start  # noqa: E402

SIZES = [("1/32", 32), ("1/48", 48), ("1/64", 64)]


def run_path(contact, n, path, directory, limit):
    sets = [f"Geometry/Cell size={1 / n!r}", f"Time/Time step={1 / n!r}",
            "Time/End time=0.5", f"Solver/Contact solver={path}",
            "Output/VTU interval=0", "Output/Progress interval=1",
            "Output/Print timings=true", f"Output/Output directory={directory}"]
    command = [contact]
    for entry in sets:
        command += ["--set", entry]
    command.append(os.path.join(ROOT, "prm", "barboteu2015_3d.prm"))
    start = time.perf_counter()
    try:
        output = subprocess.run(command, stdout=subprocess.PIPE,
                                stderr=subprocess.STDOUT, text=True,
                                timeout=limit).stdout
        finished = True
    except subprocess.TimeoutExpired as expired:
        output = (expired.stdout or b"").decode() if isinstance(
            expired.stdout, bytes) else (expired.stdout or "")
        finished = False
    wall = time.perf_counter() - start
    rows = []
    series = os.path.join(directory, "time_series.csv")
    if os.path.exists(series):
        with open(series) as file:
            rows = [row for row in csv.DictReader(file) if int(row["step"]) > 0]
    slipping = [row for row in rows if int(row["n_slip"]) > 0]

    def timer(section):
        for line in output.splitlines():
            if line.startswith(f"| {section} "):
                return float(line.split("|")[3].strip().rstrip("s"))
        return 0.

    def gamma3():
        for line in output.splitlines():
            if "free nodes on Gamma_3" in line:
                return int(line.split(" free nodes")[0].split()[-1])
        return 0

    def unknowns():
        for line in output.splitlines():
            if " unknowns, " in line:
                return int(line.split(" unknowns")[0].split()[-1])
        return 0

    return {
        "finished": finished, "steps": len(rows), "wall": wall,
        "unknowns": unknowns(), "gamma3": gamma3(),
        "delassus": timer("Delassus operator"),
        "factorization": timer("Factorization"),
        "slip steps": len(slipping),
        "newton": sum(int(r["newton_iterations"]) for r in slipping),
        "solves": sum(int(r["solves_with_K"]) for r in slipping),
    }


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--out", default=os.path.join(ROOT, "bench", "auto_path.md"))
    parser.add_argument("--limit", type=float, default=900)
    arguments = parser.parse_args()
    contact = build()
    lines = table_start([
        "h = k", "path", "unknowns", "tangential unknowns of Gamma_3",
        "steps (of T/k)", "wall [s]", "building D [s]", "factorising K [s]",
        "slipping steps", "Newton iterations in them",
        "solves with K in them"])
    ratios = []
    with tempfile.TemporaryDirectory() as tmp:
        for label, n in SIZES:
            r = {}
            for path in ("Delassus", "constraints"):
                x = run_path(contact, n, path, f"{tmp}/{n}-{path}",
                             arguments.limit)
                r[path] = x
                steps = f"{x['steps']} (of {n // 2})" + (
                    "" if x["finished"] else ", stopped at the limit")
                line = (f"| {label} | {path} | {x['unknowns']} | "
                        f"{2 * x['gamma3']} | {steps} | {x['wall']:.1f} | "
                        f"{x['delassus']:.1f} | {x['factorization']:.1f} | "
                        f"{x['slip steps']} | {x['newton']} | {x['solves']} |")
                lines.append(line)
                print(line, flush=True)
            if r["Delassus"]["finished"] and r["constraints"]["finished"]:
                ratios.append(
                    f"h = {label}: the constraints path took "
                    f"{r['constraints']['wall'] / r['Delassus']['wall']:.1f} "
                    f"times as long as the Delassus path.")
            elif r["Delassus"]["finished"]:
                ratios.append(
                    f"h = {label}: the Delassus path finished in "
                    f"{r['Delassus']['wall']:.0f} s; the constraints path "
                    f"finished {r['constraints']['steps']} of {n // 2} steps "
                    f"in {r['constraints']['wall']:.0f} s.")
    lines += ["", "prm/barboteu2015_3d.prm to t = 0.5, CHOLMOD, the default "
              "friction method, one process."] + [""] + ratios
    print("\n".join([""] + ratios))
    with open(arguments.out, "w") as file:
        file.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
