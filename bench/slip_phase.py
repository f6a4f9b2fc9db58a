#!/usr/bin/env python3
"""Per-phase cost of one long run, from its own records: reads the run's
time_series.csv (solves with K, CG iterations, stick/slip counts per step)
and its console logs (the progress lines' elapsed wall time; a run resumed
from a checkpoint has one log per start), and writes a Markdown section and,
with --plot (needs python3-matplotlib), a plot of solves with K, CG
iterations and wall seconds per step against t.

    python3 bench/slip_phase.py RUN_DIRECTORY LOG [LOG ...] \
        [--out section.md] [--plot figure.png]

The phases: stick (no node slips), slip onset (fewer than a tenth of the
nodes of Gamma_3 slip), wide slip zone (the rest). A step's wall time is the
difference of the elapsed times of two consecutive progress lines of one
log ('Output/Progress interval = 1'); the first step of each log also holds
the setup and is left out of the seconds. Nothing is estimated: a phase the
run did not reach is reported as not reached.
"""
import argparse
import csv
import os
import re
import statistics

PROGRESS = re.compile(r"^Step +(\d+)/(\d+) .*\[([0-9.e+]+) s, ")


def wall_per_step(logs):
    seconds = {}
    for log in logs:
        previous = None
        for line in open(log):
            match = PROGRESS.match(line)
            if not match:
                continue
            step, elapsed = int(match.group(1)), float(match.group(3))
            if previous is not None and step == previous[0] + 1:
                seconds[step] = elapsed - previous[1]
            previous = (step, elapsed)
    return seconds


def phase_of(row, n_nodes):
    slipping = int(row["n_slip"])
    if slipping == 0:
        return "stick"
    return "slip onset" if slipping < 0.1 * n_nodes else "wide slip zone"


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("run")
    parser.add_argument("logs", nargs="+")
    parser.add_argument("--out", default=None)
    parser.add_argument("--plot", default=None)
    arguments = parser.parse_args()

    rows = [r for r in csv.DictReader(open(os.path.join(arguments.run, "time_series.csv")))
            if int(r["step"]) > 0]
    n_nodes = int(rows[0]["n_stick"]) + int(rows[0]["n_slip"])
    seconds = wall_per_step(arguments.logs)
    total_steps = max(int(PROGRESS.match(line).group(2))
                      for log in arguments.logs for line in open(log)
                      if PROGRESS.match(line))

    lines = [f"Steps run: {len(rows)} of {total_steps} (t = {float(rows[-1]['time']):.4f}); "
             f"{n_nodes} nodes on Gamma_3.", "",
             "| phase | steps | t | solves with K per step | CG iterations per step "
             "| wall seconds per step (median, min-max) |",
             "|---|---|---|---|---|---|"]
    for phase in ("stick", "slip onset", "wide slip zone"):
        chosen = [r for r in rows if phase_of(r, n_nodes) == phase]
        if not chosen:
            lines.append(f"| {phase} | not reached | | | | |")
            continue
        solves = sum(int(r["solves_with_K"]) for r in chosen) / len(chosen)
        cg = sum(int(r["cg_iterations"]) for r in chosen) / len(chosen)
        timed = [seconds[int(r["step"])] for r in chosen if int(r["step"]) in seconds]
        wall = (f"{statistics.median(timed):.1f} ({min(timed):.1f}-{max(timed):.1f})"
                if timed else "not timed")
        lines.append(f"| {phase} | {chosen[0]['step']}-{chosen[-1]['step']} ({len(chosen)}) "
                     f"| {float(chosen[0]['time']):.3f}-{float(chosen[-1]['time']):.3f} "
                     f"| {solves:.1f} | {cg:.0f} | {wall} |")
    slipping = [r for r in rows if int(r["n_slip"]) > 0]
    if slipping:
        lines += ["", f"Solves with K per slipping step, on average: "
                  f"{sum(int(r['solves_with_K']) for r in slipping) / len(slipping):.1f} "
                  f"over {len(slipping)} steps."]
    timed_total = sum(seconds.values())
    lines.append(f"Wall time of the timed steps: {timed_total:.0f} s "
                 f"({len(seconds)} steps).")
    text = "\n".join(lines) + "\n"
    print(text, end="")
    if arguments.out:
        with open(arguments.out, "w") as file:
            file.write(text)

    if arguments.plot:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        t = [float(r["time"]) for r in rows]
        figure, axes = plt.subplots(3, 1, sharex=True, figsize=(7, 7))
        axes[0].plot(t, [int(r["solves_with_K"]) for r in rows], ".-")
        axes[0].set_ylabel("solves with K")
        axes[1].plot(t, [int(r["cg_iterations"]) for r in rows], ".-")
        axes[1].set_ylabel("CG iterations")
        timed_rows = [r for r in rows if int(r["step"]) in seconds]
        axes[2].plot([float(r["time"]) for r in timed_rows],
                     [seconds[int(r["step"])] for r in timed_rows], ".-")
        axes[2].set_ylabel("wall s per step")
        axes[2].set_xlabel("t")
        for axis in axes:
            axis.grid(True, alpha=0.3)
        figure.tight_layout()
        figure.savefig(arguments.plot, dpi=120)


if __name__ == "__main__":
    main()
