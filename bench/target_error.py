#!/usr/bin/env python3
"""Does 'Accuracy/Target error' find a run that is accurate enough, and
cheaply? On the manufactured solution with stick and slip
(prm/manufactured_slip_front.prm) each target (relative, in the largest
V-error over time) runs once with the target; then the cheapest setting of
bench/work_precision.md whose measured max V-error meets the same target
runs on its own. Both are timed in this run, three times each (the median
is printed): by the program's own wall time (pilots + the chosen run + its
estimate, against the one run) and by the wall time of the whole process
(which adds the start-up of the libraries to both).

    python3 bench/target_error.py [--out bench/target_error.md]

Every number printed is measured in this run, except the errors quoted
from bench/work_precision.md to pick the setting to compare with.
"""
import argparse
import math
import os
import re
import statistics
import sys
import tempfile

from run import ROOT, build, machine, number, run
from work_precision import MANUFACTURED

TARGETS = [1e-2, 3e-3, 1e-3]
REPEAT = 3
COMMON = ["Convergence study/Levels=0", "Output/Print timings=true",
          "Output/Progress interval=0", "Output/VTU interval=0"]


def work_precision_rows():
    """The manufactured table of bench/work_precision.md as dicts."""
    rows, header = [], None
    for line in open(os.path.join(ROOT, "bench", "work_precision.md")):
        if not line.startswith("|"):
            if header and rows:
                break
            continue
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if cells[0] == "setting":
            header = cells
        elif header and not cells[0].startswith("---"):
            rows.append(dict(zip(header, cells)))
    return rows


def median_run(contact, prm, sets, pattern):
    """Median over REPEAT runs of (the program's own time, process time);
    the output of the last run."""
    own, process = [], []
    for _ in range(REPEAT):
        output, wall, _ = run(contact, prm, sets)
        own.append(number(pattern, output))
        process.append(wall)
    return statistics.median(own), statistics.median(process), output


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--out", default=os.path.join(ROOT, "bench",
                                                      "target_error.md"))
    arguments = parser.parse_args()
    contact = build()
    prm = os.path.join(ROOT, "prm", "manufactured_slip_front.prm")
    settings = dict(MANUFACTURED)
    table = []
    with tempfile.TemporaryDirectory() as directory:
        for target in TARGETS:
            own, process, output = median_run(
                contact, prm, COMMON + [
                    f"Accuracy/Target error={target}",
                    f"Output/Output directory={directory}/target"],
                r"Wall time: pilots [0-9.e-]+ s, the chosen run with its "
                r"estimate [0-9.e-]+ s, total ([0-9.e-]+) s")
            pilots = number(r"Wall time: pilots ([0-9.e-]+) s", output)
            size = number(r"times its size ([0-9.e-]+)\)", output)
            exact = number(r"Exact max V-error of the chosen run: ([0-9.e-]+)",
                           output)
            estimated = number(r"estimated error ([0-9.e-]+) \(error_estimate",
                               output)
            chosen = re.search(r"chosen degree (\d), h = ([0-9.e-]+), "
                               r"k = ([0-9.e-]+) \((\d+) unknowns, (\d+) steps",
                               output).groups()
            absolute = target * size
            # The cheapest setting of the work-precision table that meets
            # the target, run here on its own.
            meeting = [row for row in work_precision_rows()
                       if float(row["max V-error"]) <= absolute]
            if not meeting:
                sys.exit(f"no setting of work_precision.md meets {absolute}")
            cheapest = min(meeting, key=lambda row: float(row["wall time [s]"]))
            sets = [s for s in settings[cheapest["setting"]]
                    if not s.startswith(("Geometry/Cell size", "Time/Time step",
                                         "Convergence study/Levels"))]
            h, k = float(cheapest["h"]), float(cheapest["k"])
            # The table rounds h and k; they are powers of 1/2.
            h, k = 2. ** round(math.log2(h)), 2. ** round(math.log2(k))
            base_own, base_process, _ = median_run(
                contact, prm, COMMON + sets + [
                    f"Geometry/Cell size={h}", f"Time/Time step={k}",
                    f"Output/Output directory={directory}/cheapest"],
                r"\nWall time: ([0-9.e-]+) s")
            table.append((target, absolute, chosen, exact, estimated, pilots,
                          own, process, cheapest["setting"], h, k,
                          cheapest["max V-error"], base_own, base_process))

    lines = [
        "# A run to a target error",
        "",
        f"Measured with `bench/target_error.py` on {machine()}, Release "
        f"build; each time the median of {REPEAT} runs.",
        "",
        "    /usr/bin/python3 bench/target_error.py",
        "",
        "Targets are relative to the largest ||eps(u_h)|| of the first pilot; "
        "'exact' is the largest V-error over all steps against the "
        "manufactured solution. The setting compared with is the cheapest "
        "row of `bench/work_precision.md` whose max V-error meets the target, "
        "run here on its own.",
        "",
        "| target | absolute | chosen: degree, h, k (unknowns, steps) | "
        "exact error | exact / target | estimated error | pilots [s] | "
        "target run, total [s] | cheapest setting (h, k; its error) | "
        "its run [s] | ratio | process: target run [s] | process: "
        "cheapest [s] | ratio |",
        "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|",
    ]
    for (target, absolute, chosen, exact, estimated, pilots, own, process,
         setting, h, k, error, base_own, base_process) in table:
        degree, ch, ck, unknowns, steps = chosen
        lines.append(
            f"| {target:g} | {absolute:.3g} | Q{degree}, {float(ch):.4g}, "
            f"{float(ck):.4g} ({unknowns}, {steps}) | {exact:.3g} | "
            f"{exact / absolute:.2f} | {estimated:.3g} | {pilots:.3f} | "
            f"{own:.3f} | {setting} ({h:g}, {k:g}; {error}) | "
            f"{base_own:.3f} | {own / base_own:.2f} | {process:.3f} | "
            f"{base_process:.3f} | {process / base_process:.2f} |")
    text = "\n".join(lines) + "\n"
    print(text)
    with open(arguments.out, "w") as out:
        out.write(text)


if __name__ == "__main__":
    main()
