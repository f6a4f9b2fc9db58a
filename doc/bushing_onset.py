#!/usr/bin/env python3
"""The slip onset of the bushing (prm/bushing.prm) under mesh refinement,
for Q1 and Q2 elements on a polygonal Gamma_3 ('Geometry/Mapping degree =
1') and on a curved one (mapping degree 2), at k = 1/256 for all runs.

For 8 x 4^m cells, m = 1, ..., 5 (Q2 with mapping degree 1 and 2 up to
m = 5, Q1 likewise), it prints a Markdown table of the unknowns, the time
of the first slip ("First slip at t = ..." of the summary, extrapolated
within its step, so that at a fixed k it moves with h alone), its change
from the next coarser mesh, the observed order log2 of the ratio of two
successive changes, the largest reaction moment relative to the largest
applied moment (time_series.csv: round-off where the rigid rotation lies
in the discrete space).

Then, for Q2 with mapping degree 1 and 2 and m = 1, ..., 4, the friction
traction at t = 0.9 (every node sticks; k = 1/64 of the scene) of the two
classes of Q2 nodes on Gamma_3, the cells' vertices and their edges'
midpoints (gamma3_history.csv), and their relative difference.

Usage: doc/bushing_onset.py path/to/contact prm/bushing.prm [largest m]
Only the Python standard library is needed; every number is measured in
the run.
"""
import csv
import math
import os
import re
import subprocess
import sys
import tempfile


def run(contact, prm, element, mapping, m, directory):
    command = [contact]
    for entry in [f"Geometry/Finite element degree={element}",
                  f"Geometry/Mapping degree={mapping}",
                  f"Geometry/Mesh refinements={m}",
                  "Time/Time step=0.00390625",
                  "Output/VTU interval=0", "Output/Progress interval=0",
                  "Output/Report times=", "Output/Print timings=false",
                  f"Output/Output directory={directory}"]:
        command += ["--set", entry]
    output = subprocess.run(command + [prm], capture_output=True, text=True,
                            check=True).stdout
    if "extrapolated" not in output:
        sys.exit(f"the first slip of Q{element}, mapping degree {mapping}, "
                 f"m = {m} is not extrapolated within its step")

    def number(pattern):
        return float(re.search(pattern, output).group(1))

    with open(os.path.join(directory, "time_series.csv")) as file:
        rows = list(csv.DictReader(file))
    reaction = max(abs(float(r["reaction_moment"])) for r in rows)
    applied = max(abs(float(r["applied_moment"])) for r in rows)
    return (int(number(r"(\d+) unknowns")),
            number(r"First slip at t = ([0-9.e+-]+)"),
            reaction / applied)


def class_tractions(contact, prm, mapping, m, directory):
    """The largest |traction| at t = 0.9 of the vertex and the midpoint
    nodes of Gamma_3 (by the angle modulo the cells' angle), where every
    node must stick."""
    command = [contact]
    for entry in ["Geometry/Finite element degree=2",
                  f"Geometry/Mapping degree={mapping}",
                  f"Geometry/Mesh refinements={m}", "Time/End time=0.9",
                  "Output/VTU interval=0", "Output/Progress interval=0",
                  "Output/Report times=", "Output/Print timings=false",
                  "Output/Gamma3 history=true",
                  f"Output/Output directory={directory}"]:
        command += ["--set", entry]
    subprocess.run(command + [prm], capture_output=True, check=True)
    with open(os.path.join(directory, "gamma3_history.csv")) as file:
        rows = list(csv.DictReader(file))
    last = rows[-1]["step"]
    cell_angle = 2 * math.pi / (8 * 2 ** m)
    largest = {}
    for row in rows:
        if row["step"] != last:
            continue
        if row["state"] != "1":
            sys.exit(f"a node slips at t = {row['time']}: choose an earlier "
                     "time")
        angle = math.atan2(float(row["y"]), float(row["x"]))
        midpoint = abs((angle / cell_angle) % 1 - 0.5) < 0.25
        traction = abs(float(row["friction_traction_t1"]))
        largest[midpoint] = max(largest.get(midpoint, 0), traction)
    return largest[False], largest[True]


def main():
    contact, prm = sys.argv[1], sys.argv[2]
    finest = int(sys.argv[3]) if len(sys.argv) > 3 else 5
    print("| element | mapping degree | m | unknowns | first slip t | "
          "change from m - 1 | order | reaction / applied moment |")
    print("|---|---|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as scratch:
        for element in (1, 2):
            for mapping in (1, 2):
                onsets, changes = [], []
                for m in range(1, finest + 1):
                    directory = os.path.join(scratch, f"q{element}m{mapping}r{m}")
                    unknowns, onset, moment = run(
                        contact, prm, element, mapping, m, directory)
                    onsets.append(onset)
                    change = order = ""
                    if m > 1:
                        changes.append(abs(onsets[-1] - onsets[-2]))
                        change = f"{changes[-1]:.2e}"
                    if len(changes) > 1:
                        order = f"{math.log2(changes[-2] / changes[-1]):.2f}"
                    print(f"| Q{element} | {mapping} | {m} | {unknowns} | "
                          f"{onset:.8f} | {change} | {order} | {moment:.1e} |",
                          flush=True)
        print("\n| mapping degree | m | traction at vertices | at midpoints "
              "| relative difference |")
        print("|---|---|---|---|---|")
        for mapping in (1, 2):
            for m in range(1, min(finest, 4) + 1):
                vertex, midpoint = class_tractions(
                    contact, prm, mapping, m,
                    os.path.join(scratch, f"classes{mapping}{m}"))
                print(f"| {mapping} | {m} | {vertex:.4f} | {midpoint:.4f} | "
                      f"{abs(vertex - midpoint) / max(vertex, midpoint):.2e} |",
                      flush=True)


if __name__ == "__main__":
    main()
