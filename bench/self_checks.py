#!/usr/bin/env python3
"""What the self-checks cost: the paper's scene as shipped
(prm/barboteu2015.prm, VTU on, timings printed), run --repeats times. The
program's TimerOutput gives the wall time of its "Self-checks" section and
of the whole run; the share of the one in the other is what this script
reports, per run and as the median.

    python3 bench/self_checks.py [--repeats 5] [--out bench/self_checks.md]

Prints the machine facts and every run's times. Everything printed is
measured in this run.
"""
import argparse
import os
import re
import statistics
import sys
import tempfile

from output import machine
from run import ROOT, build, run


def timer(name, text):
    match = re.search(r"\| " + re.escape(name) + r" +\| +\d+ \| +([0-9.e+-]+)s \|",
                      text)
    if not match:
        sys.exit(f"no timer '{name}' in the output")
    return float(match.group(1))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--out",
                        default=os.path.join(ROOT, "bench", "self_checks.md"))
    arguments = parser.parse_args()
    contact = build()
    lines = [machine(), "",
             "`prm/barboteu2015.prm` as shipped (h = k = 1/128, 141 steps, "
             "VTU every 8 steps), the TimerOutput of each run:", "",
             "| run | self-checks [s] | whole run [s] | share |",
             "|---|---|---|---|"]
    shares = []
    with tempfile.TemporaryDirectory() as directory:
        for repeat in range(arguments.repeats):
            output, _, _ = run(contact, os.path.join(ROOT, "prm", "barboteu2015.prm"),
                               [f"Output/Output directory={directory}/run"])
            checks = timer("Self-checks", output)
            total = float(re.search(
                r"Total wallclock time elapsed since start +\| +([0-9.e+-]+)s",
                output).group(1))
            shares.append(checks / total)
            lines.append(f"| {repeat + 1} | {checks:.4f} | {total:.3f} | "
                         f"{100 * checks / total:.1f} % |")
    lines += ["", f"Median share of the self-checks: "
              f"{100 * statistics.median(shares):.1f} % of the run."]
    text = "\n".join(lines) + "\n"
    print(text)
    with open(arguments.out, "w") as out:
        out.write(text)


if __name__ == "__main__":
    main()
