#!/usr/bin/env python3
"""The extremes of the data and the
stability map of the convexification, in one command:

    python3 bench/extremes.py [--contact build/contact]

Every case is a whole run of the paper's scene (prm/barboteu2015.prm) at
h = 1/16 with a few entries changed, with 'Solver/Friction method =
convexification'. For each it records whether the run
converged (exit status 0), the steps, the convexification and active set
iterations (mean and largest per step), the largest relative residual of the
energy identity, whether 'nan' or 'inf' appears anywhere in the console or
in time_series.csv, and for failures the first line of the message.

The map runs the convexification over alpha x k and S x k and draws, on the
same axes, the per-step convexity limit S (a - b) alpha < X(k) that the
program prints (measured per k) and the paper's condition (3.22),
S < min(mu2 / (2 a C0^2), mu2 / ((a - b) alpha C0^2)), with C0^2 measured as
1/X for the strain-norm problem (rho = 0, mu1 = 0, mu2 = 1, E = 1e-9, k = 1).
Writes doc/stability.md and doc/stability_map.png. Every number in them is
measured by this script.
"""
import argparse
import csv
import math
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from run import machine  # noqa: E402  (bench/run.py)
PRM = os.path.join(ROOT, "prm", "barboteu2015.prm")
# The paper's method, whose stability this measures (the program's default
# is Newton, with the convexification as its fallback).
BASE = ["Solver/Friction method=convexification",
        "Geometry/Cell size=0.0625", "Time/Time step=0.0625", "Output/VTU interval=0",
        "Output/Progress interval=0", "Output/Print timings=false", "Output/Report times="]


def run(contact, sets, directory):
    command = [contact]
    for entry in BASE + sets + [f"Output/Output directory={directory}"]:
        command += ["--set", entry]
    process = subprocess.run(command + [PRM], stdout=subprocess.PIPE,
                             stderr=subprocess.STDOUT, text=True)
    text = process.stdout
    result = {"converged": process.returncode == 0, "output": text}
    rows = []
    series = os.path.join(directory, "time_series.csv")
    if os.path.exists(series):
        with open(series) as f:
            rows = list(csv.DictReader(f))
        with open(series) as f:
            text += f.read()
    result["nan"] = re.search(r"\b(nan|inf)\b", text, re.IGNORECASE) is not None
    steps = [r for r in rows if int(r["step"]) > 0]
    result["steps"] = len(steps)
    result["final"] = (f"{steps[-1]['n_stick']} / {steps[-1]['n_slip']}" if steps else "-")
    for key in ["convexification_iterations", "active_set_iterations"]:
        values = [int(r[key]) for r in steps]
        result[key] = (sum(values) / len(values) if values else 0, max(values, default=0))
    match = re.search(r"energy identity from the matrices \(the solve\): ([0-9.e+-]+)", text)
    result["energy"] = match.group(1) if match else "-"
    match = re.search(r"convex while S \(a - b\) alpha < ([0-9.e+-]+)", text)
    result["limit"] = float(match.group(1)) if match else None
    match = re.search(r"Error:\s+(.*)", process.stdout)
    result["message"] = match.group(1)[:160] if match else ""
    return result


EXTREMES = [
    ("paper's data (S = 100, alpha = 200)", []),
    ("alpha = 0 (law constant, mu = a)", ["Friction/Friction law=constant"]),
    ("alpha = 1e4", ["Friction/alpha=1e4"]),
    ("a >> b (a = 10, b = 0.001)", ["Friction/a=10", "Friction/b=0.001"]),
    ("S = 0", ["Friction/Friction bound S=0"]),
    ("S = 1e5", ["Friction/Friction bound S=1e5"]),
    ("Poisson ratio 0.4999", ["Material/Poisson ratio=0.4999"]),
    ("mu1 = mu2 = 0 (no viscosity)", ["Material/Viscosity mu1=0", "Material/Viscosity mu2=0"]),
    ("rho = 1e-9", ["Material/Density=1e-9"]),
    ("rho = 0 (quasi-static)", ["Material/Density=0"]),
    ("k = 1e-6 (100 steps to t = 1e-4)", ["Time/Time step=1e-6", "Time/End time=1e-4"]),
    ("k = T (one step)", ["Time/Time step=1.1"]),
    ("all of Gamma_3 slips (top load 5000 t tangential)",
     ["Boundary conditions/Tractions=3: 5000*t; -600*t"]),
    ("S = 1e5, alpha = 1e4, k = T", ["Friction/Friction bound S=1e5", "Friction/alpha=1e4",
                                     "Time/Time step=1.1"]),
]

ALPHAS = [0.1, 1, 10, 100, 200, 1000, 1e4]
SS = [0.1, 1, 10, 100, 1000, 1e4, 1e5]
KS = [0.1, 0.03, 0.01, 0.001]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--contact", default=os.path.join(ROOT, "build", "contact"))
    arguments = parser.parse_args()
    contact = os.path.abspath(arguments.contact)
    lines = ["# Extremes and the stability map", "",
             "Measured by `python3 bench/extremes.py` (paper's scene, h = 1/16, k = 1/16 unless "
             f"changed; {machine().split(', load average')[0]}). 'nan' means 'nan' or 'inf' appears in the console or in "
             "time_series.csv.", "",
             "| case | converged | steps | stick / slip nodes at the end "
             "| convexification it. mean / max | active set it. mean / max "
             "| energy residual | nan | message |",
             "|---|---|---|---|---|---|---|---|---|"]
    failures = 0
    with tempfile.TemporaryDirectory() as tmp:
        for i, (name, sets) in enumerate(EXTREMES):
            r = run(contact, sets, f"{tmp}/extreme{i}")
            c, a = r["convexification_iterations"], r["active_set_iterations"]
            line = (f"| {name} | {'yes' if r['converged'] else 'NO'} | {r['steps']} | {r['final']} "
                    f"| {c[0]:.1f} / {c[1]} | {a[0]:.1f} / {a[1]} | {r['energy']} "
                    f"| {'YES' if r['nan'] else 'no'} | {r['message']} |")
            lines.append(line)
            print(line, flush=True)
            failures += r["nan"]

        # C0^2 of the paper's trace inequality, from the strain-norm problem.
        r = run(contact, ["Material/Density=0", "Material/Viscosity mu1=0",
                          "Material/Viscosity mu2=1", "Material/Young's modulus=1e-9",
                          "Time/Time step=1", "Time/End time=1"], f"{tmp}/trace")
        c0_squared = 1 / r["limit"]
        mu2, a, b = 100., 1., 0.1

        def s_322(alpha):
            return min(mu2 / (2 * a * c0_squared), mu2 / ((a - b) * alpha * c0_squared))

        lines += ["", f"Trace constant of V_h on Gamma_3 (h = 1/16): C0^2 = {c0_squared:.3f}; "
                  f"(3.22) for the paper's data (mu2 = 100, a = 1, b = 0.1, alpha = 200): "
                  f"S < {s_322(200):.3f}.", ""]

        maps = {}
        for name, values, entry in [("alpha", ALPHAS, "Friction/alpha"),
                                    ("S", SS, "Friction/Friction bound S")]:
            lines += [f"Convexification over {name} x k (other data the paper's: "
                      + ("S = 100" if name == "alpha" else "alpha = 200")
                      + "): mean / largest iterations per step, NO = not converged "
                      "within 200 iterations in some step.", "",
                      f"| {name} \\ k | " + " | ".join(str(k) for k in KS) + " |",
                      "|---|" + "---|" * len(KS)]
            table = {}
            for value in values:
                cells = []
                for k in KS:
                    r = run(contact, [f"{entry}={value}", f"Time/Time step={k}"],
                            f"{tmp}/map")
                    table[(value, k)] = r
                    c = r["convexification_iterations"]
                    cells.append(f"{c[0]:.1f} / {c[1]}" if r["converged"] else "NO")
                    failures += r["nan"]
                line = f"| {value:g} | " + " | ".join(cells) + " |"
                lines.append(line)
                print(line, flush=True)
            limits = {k: table[(values[0], k)]["limit"] for k in KS}
            lines += ["", "Per-step convexity limit X(k) of S (a - b) alpha (console line "
                      "'Gamma_3: ... convex while'): "
                      + ", ".join(f"k = {k}: {limits[k]:.3g}" for k in KS), ""]
            maps[name] = (values, table, limits)

        lines += ["![stability map](stability_map.png)", ""]
        plot(maps, s_322, os.path.join(ROOT, "doc", "stability_map.png"))
    with open(os.path.join(ROOT, "doc", "stability.md"), "w") as out:
        out.write("\n".join(lines) + "\n")
    print(f"\ncases printing nan/inf: {failures}")
    sys.exit(1 if failures else 0)


def plot(maps, s_322, name):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    figure, axes = plt.subplots(1, 2, figsize=(11, 5))
    a, b = 1., 0.1
    for axis, key in zip(axes, ["alpha", "S"]):
        values, table, limits = maps[key]
        for (value, k), r in table.items():
            if r["converged"]:
                mean = r["convexification_iterations"][0]
                axis.scatter(k, value, c=[[min(mean / 30, 1), 0.2, 1 - min(mean / 30, 1)]],
                             s=60, marker="o")
                axis.annotate(f"{mean:.0f}", (k, value), textcoords="offset points",
                              xytext=(6, 4), fontsize=7)
            else:
                axis.scatter(k, value, c="k", s=80, marker="x")
        ks = sorted(limits)
        other = 100. if key == "alpha" else 200.
        axis.plot(ks, [limits[k] / (other * (a - b)) for k in ks], "g-",
                  label="per step convex: S (a-b) alpha = X(k)")
        if key == "alpha":
            # (3.22) also needs mu2 / 2 > S a C0^2, which S = 100 violates:
            # there is no alpha for which it holds on this panel.
            axis.plot([], [], "r--", label="(3.22) fails for every alpha at S = 100")
        else:
            axis.axhline(s_322(200), color="r", ls="--", label="(3.22): S < %.3g" % s_322(200))
        axis.set_xscale("log")
        axis.set_yscale("log")
        axis.set_xlabel("time step k [s]")
        axis.set_ylabel(key)
        axis.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.14), ncol=2)
        axis.set_title(f"convexification over {key} x k (o: mean iterations, x: failed)",
                       fontsize=9)
    figure.tight_layout()
    figure.savefig(name, dpi=110)


if __name__ == "__main__":
    main()
