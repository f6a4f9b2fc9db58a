#!/usr/bin/env python3
"""Scan the friction bound S of the paper's scene and its Figure 3 variants.

Runs the program itself (contact --set ...) for every S and every friction
law variant, and prints a Markdown table of what Gamma_3 does:

  - the largest number of slipping nodes at any step with t <= 0.3,
  - the stick/slip counts and the slip zone at t = 1.1.

Usage: doc/scan_friction_bound.py path/to/contact prm/barboteu2015.prm [S ...]
Only the Python standard library is needed.
"""
import csv
import os
import re
import subprocess
import sys
import tempfile

VARIANTS = [("a = 1, b = 0.1 (Fig. 2)", "1", "0.1"),
            ("a = b = 0.1 (Fig. 3)", "0.1", "0.1"),
            ("a = b = 1 (Fig. 3)", "1", "1")]
DEFAULT_S = [1, 2, 5, 10, 20, 30, 40, 60, 80, 100, 120, 160, 200, 300, 500]


def run(contact, prm, S, a, b, directory):
    command = [contact,
               "--set", f"Friction/Friction bound S={S}",
               "--set", f"Friction/a={a}", "--set", f"Friction/b={b}",
               "--set", "Solver/Max convexification iterations=2000",
               "--set", "Output/VTU interval=0",
               "--set", "Output/Progress interval=0",
               "--set", "Output/Print timings=false",
               "--set", "Output/Report times=1.1",
               "--set", f"Output/Output directory={directory}", prm]
    result = subprocess.run(command, capture_output=True, text=True)
    if result.returncode != 0:
        return None
    with open(os.path.join(directory, "time_series.csv")) as f:
        rows = list(csv.DictReader(f))
    early = max(int(r["n_slip"]) for r in rows if float(r["time"]) <= 0.3 + 1e-12)
    last = rows[-1]
    zone = re.search(r"slip zone x in \[([^\]]*)\]", result.stdout)
    return (early, int(last["n_stick"]), int(last["n_slip"]),
            "[" + zone.group(1) + "]" if zone else "none")


def main():
    contact, prm = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    values = [float(s) for s in sys.argv[3:]] or DEFAULT_S
    print("| S | law | max slip nodes, t <= 0.3 | stick / slip at t = 1.1 "
          "| slip zone at t = 1.1 |")
    print("|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as tmp:
        for S in values:
            for name, a, b in VARIANTS:
                outcome = run(contact, prm, S, a, b, os.path.join(tmp, "r"))
                if outcome is None:
                    print(f"| {S:g} | {name} | did not converge | | |")
                else:
                    early, stick, slip, zone = outcome
                    print(f"| {S:g} | {name} | {early} | {stick} / {slip} "
                          f"| {zone} |", flush=True)


if __name__ == "__main__":
    main()
