#!/usr/bin/env python3
"""Benchmark of the paper's scene: builds the program in Release
and measures, on this machine, whole runs with VTU output off and the time
series on.

    python3 bench/run.py [--sizes 32,64,128,256] [--out bench/results.md]

For h = k = 1/N it prints the number of unknowns, time steps, wall time,
time per step, mean convexification and active set iterations per step, the
peak memory of the process and the ratio of the time per step to one
forward/back substitution with the factor of K (the program measures both),
then the same at 1/64 on the straightforward path ('Solver/Contact solver
= constraints') and the ratio of the two, then the wall time of the Figure 4 study (prm/barboteu2015_convergence.prm
taken down to 1/256). Everything printed is measured in this run; the
table goes to --out as Markdown.
"""
import argparse
import math
import os
import platform
import re
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def build(target="contact"):
    build_dir = os.path.join(ROOT, "build-bench")
    subprocess.run(["cmake", "-S", ROOT, "-B", build_dir, "-DCMAKE_BUILD_TYPE=Release"],
                   check=True, stdout=subprocess.DEVNULL)
    subprocess.run(["cmake", "--build", build_dir, "-j2", "--target", target],
                   check=True, stdout=subprocess.DEVNULL)
    return os.path.join(build_dir, target)


def run(contact, prm, sets):
    """Runs contact (a path, or a command list such as mpirun ... contact),
    returns (stdout, wall seconds, peak memory in MB)."""
    command = list(contact) if isinstance(contact, list) else [contact]
    for entry in sets:
        command += ["--set", entry]
    start = time.perf_counter()
    process = subprocess.Popen(command + [prm], stdout=subprocess.PIPE,
                               stderr=subprocess.STDOUT, text=True)
    output = process.stdout.read()
    _, status, usage = os.wait4(process.pid, 0)
    wall = time.perf_counter() - start
    if status != 0:
        sys.exit(f"contact failed:\n{output}")
    return output, wall, usage.ru_maxrss / 1024.


def own_estimate(contact, prm, sets, separate=False):
    """The program's own error estimate of the V-norm of u at T for the
    scene prm with sets: the row of its report as a dict (column -> text),
    and the unknowns at T of the run (for a run adapted during itself)."""
    command = [contact] + sum((["--set", s] for s in sets + [
        "Accuracy/Estimate error=true",
        f"Accuracy/Separate space and time={'true' if separate else 'false'}"]),
        []) + [prm]
    result = subprocess.run(command, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True)
    if result.returncode != 0:
        sys.exit("contact failed:\n" + result.stdout)
    lines = result.stdout.splitlines()
    first = next(i for i, line in enumerate(lines) if line.startswith("| quantity "))
    header = [c.strip() for c in lines[first].strip().strip("|").split("|")]
    for line in lines[first + 1:]:
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if cells[0] == "V-norm of u":
            row = dict(zip(header, cells))
            break
    unknowns = re.search(r"Mesh: \d+ cells, Q\d, (\d+) unknowns", result.stdout).group(1)
    adapted = re.search(r"unknowns at T: (\d+)", result.stdout)
    return row, adapted.group(1) if adapted else unknowns


def number(pattern, text):
    match = re.search(pattern, text)
    if not match:
        sys.exit(f"cannot find '{pattern}' in the output")
    return float(match.group(1))


def machine():
    model = "unknown CPU"
    for line in open("/proc/cpuinfo"):
        if line.startswith("model name"):
            model = line.split(":", 1)[1].strip()
            break
    memory = 0
    for line in open("/proc/meminfo"):
        if line.startswith("MemTotal"):
            memory = int(line.split()[1]) / 1024 ** 2
    return (f"{model}, {os.cpu_count()} cores, {memory:.1f} GB, "
            f"{platform.system()} {platform.release()}, load average "
            f"{os.getloadavg()[0]:.2f} at the start")


def mpi_launcher(processes):
    """The command prefix that starts contact on this many processes. Open
    MPI refuses root without the two variables; oversubscription is for
    machines with fewer cores than processes."""
    if processes == 1:
        return []
    os.environ.setdefault("OMPI_ALLOW_RUN_AS_ROOT", "1")
    os.environ.setdefault("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")
    os.environ.setdefault("OMPI_MCA_rmaps_base_oversubscribe", "1")
    return ["mpirun", "-np", str(processes)]


def start(results, columns):
    """For a script whose only option is --out (default bench/<results>):
    builds the program and starts the table. Returns the program, the
    output file and the table's first lines."""
    parser = argparse.ArgumentParser()
    parser.add_argument("--out", default=os.path.join(ROOT, "bench", results))
    out = parser.parse_args().out
    return build(), out, table_start(columns)


def table_start(columns):
    """The machine, then the header of a Markdown table with these columns;
    printed at once and returned as the first lines of the results."""
    lines = [f"Machine: {machine()}", "", "| " + " | ".join(columns) + " |",
             "|" + "---|" * len(columns)]
    print("\n".join(lines), flush=True)
    return lines


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--sizes", default="32,64,128,256")
    parser.add_argument("--out", default=os.path.join(ROOT, "bench", "results.md"))
    arguments = parser.parse_args()
    contact = build()
    prm = os.path.join(ROOT, "prm", "barboteu2015.prm")

    lines = table_start(["h = k", "unknowns", "factor nonzeros", "steps", "wall [s]",
                         "per step [ms]", "convexification it./step",
                         "active set it./step", "peak memory [MB]", "step / substitution"])
    growth = []
    fast = None
    with tempfile.TemporaryDirectory() as tmp:
        for n in [int(s) for s in arguments.sizes.split(",")]:
            output, wall, memory = run(contact, prm, [
                f"Geometry/Cell size={1. / n}", f"Time/Time step={1. / n}",
                "Output/VTU interval=0", "Output/Progress interval=0",
                "Output/Print timings=true", f"Output/Output directory={tmp}/{n}"])
            unknowns = number(r"Q1, (\d+) unknowns", output)
            steps = number(r"Done: (\d+) steps", output)
            convexification = number(r"(\d+) convexification iterations", output)
            active_set = number(r"(\d+) active set iterations", output)
            per_step = number(r"Time per step ([0-9.e+-]+) ms", output)
            ratio = number(r"ms = ([0-9.e+-]+) substitutions", output)
            factor = number(r"Factor of K: (\d+) nonzeros", output)
            growth.append((n, unknowns, factor, per_step))
            if n == 64:
                fast = (per_step, wall)
            line = (f"| 1/{n} | {unknowns:.0f} | {factor:.0f} | {steps:.0f} | {wall:.2f} "
                    f"| {per_step:.2f} "
                    f"| {convexification / steps:.1f} | {active_set / steps:.1f} "
                    f"| {memory:.0f} | {ratio:.2f} |")
            lines.append(line)
            print(line, flush=True)

        # Growth with the number of unknowns N between successive sizes:
        # time per step ~ N^a against the factor's size ~ N^b.
        for (n0, N0, f0, t0), (n1, N1, f1, t1) in zip(growth, growth[1:]):
            line = (f"\n1/{n0} -> 1/{n1}: time per step ~ N^{math.log(t1 / t0) / math.log(N1 / N0):.2f}, "
                    f"factor size ~ N^{math.log(f1 / f0) / math.log(N1 / N0):.2f}")
            lines.append(line)
            print(line, flush=True)

        # The straightforward path (active set as constraints, one
        # factorisation per Newton step) at 1/64, against the row above.
        if fast:
            output, wall, memory = run(contact, prm, [
                "Geometry/Cell size=0.015625", "Time/Time step=0.015625",
                "Solver/Contact solver=constraints",
                "Output/VTU interval=0", "Output/Progress interval=0",
                "Output/Print timings=true", f"Output/Output directory={tmp}/constraints"])
            per_step = number(r"Time per step ([0-9.e+-]+) ms", output)
            line = (f"\nAt h = k = 1/64, straightforward path ('Solver/Contact solver = constraints'): "
                    f"{per_step:.2f} ms per step, {wall:.2f} s wall; Delassus path (row above): "
                    f"{fast[0]:.2f} ms per step, {fast[1]:.2f} s wall; per step the Delassus path is "
                    f"{per_step / fast[0]:.1f} times faster.")
            lines.append(line)
            print(line, flush=True)

        output, wall, memory = run(contact,
                                   os.path.join(ROOT, "prm", "barboteu2015_convergence.prm"),
                                   ["Convergence study/Levels=7",
                                    f"Output/Output directory={tmp}/figure4"])
        line = (f"\nFigure 4 study, h = k = 1/2 ... 1/256 (prm/barboteu2015_convergence.prm "
                f"with Levels = 7): {wall:.1f} s wall, peak memory {memory:.0f} MB.")
        lines.append(line)
        print(line)
    with open(arguments.out, "w") as out:
        out.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
