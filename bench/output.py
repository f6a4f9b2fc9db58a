#!/usr/bin/env python3
"""What the VTU output costs: the paper's scene (prm/barboteu2015.prm, its
VTU every 8 steps and at the report times) against the same run with
'Output/VTU interval = 0', each run --repeats times, alternating, in one
invocation of this script.

    python3 bench/output.py [--repeats 5] [--out bench/output.md]

Prints the machine facts, the wall times of every run, the medians and their
ratio, the number and size of the VTU files. Everything printed is measured
in this run.
"""
import argparse
import os
import platform
import statistics
import tempfile

from run import ROOT, build, run


def machine():
    cores = os.cpu_count()
    model = "unknown"
    with open("/proc/cpuinfo") as cpuinfo:
        for line in cpuinfo:
            if line.startswith("model name"):
                model = line.split(":", 1)[1].strip()
                break
    return (f"Machine: {model}, {cores} cores, {platform.system()} "
            f"{platform.release()}, load average {os.getloadavg()[0]:.2f} "
            "at the start")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--out", default=os.path.join(ROOT, "bench", "output.md"))
    arguments = parser.parse_args()
    contact = build()
    prm = os.path.join(ROOT, "prm", "barboteu2015.prm")
    lines = [machine(), ""]
    times = {"VTU interval = 8": [], "VTU interval = 0": []}
    with tempfile.TemporaryDirectory() as directory:
        for repeat in range(arguments.repeats):
            for label in times:
                interval = label.split()[-1]
                out = os.path.join(directory, f"vtu{interval}")
                _, wall, _ = run(contact, prm,
                                 [f"Output/VTU interval={interval}",
                                  f"Output/Output directory={out}",
                                  "Output/Progress interval=0",
                                  "Output/Print timings=false"])
                times[label].append(wall)
        files = [f for f in os.listdir(os.path.join(directory, "vtu8"))
                 if f.endswith(".vtu")]
        size = sum(os.path.getsize(os.path.join(directory, "vtu8", f))
                   for f in files)
    lines.append("| run | wall times [s] | median [s] |")
    lines.append("|---|---|---|")
    for label, walls in times.items():
        lines.append(f"| {label} | {', '.join(f'{w:.2f}' for w in walls)} | "
                     f"{statistics.median(walls):.2f} |")
    ratio = (statistics.median(times["VTU interval = 8"]) /
             statistics.median(times["VTU interval = 0"]))
    lines += ["",
              f"With VTU output: {len(files)} VTU files, {size / 1e6:.1f} MB; "
              f"the run costs {ratio:.2f} times the run without (medians)."]
    text = "\n".join(lines) + "\n"
    print(text)
    with open(arguments.out, "w") as out:
        out.write("# The cost of the VTU output\n\n"
                  "Written by `python3 bench/output.py` (see its docstring).\n\n"
                  + text)


if __name__ == "__main__":
    main()
