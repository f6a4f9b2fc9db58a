#!/usr/bin/env python3
"""Plot the tables that a convergence study writes (convergence.txt):
error against h, and error against the wall time of each run.

Usage: doc/plot_convergence.py out.png label=path/convergence.txt ...
Every error column of every table is drawn (rate columns are skipped).
Needs matplotlib (Debian: python3-matplotlib).
"""
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt


def read_org_table(path):
    rows = [[c.strip() for c in line.strip().strip("|").split("|")]
            for line in open(path) if line.startswith("|")]
    header, body = rows[0], rows[1:]
    return {name: [row[i] for row in body] for i, name in enumerate(header)}


def main():
    output, tables = sys.argv[1], sys.argv[2:]
    figure, (by_h, by_time) = plt.subplots(1, 2, figsize=(11, 4.2),
                                           constrained_layout=True)
    for item in tables:
        label, path = item.rsplit("=", 1)
        table = read_org_table(path)
        h = [float(v) for v in table["h"]]
        for column in table:
            if not ("error" in column or "difference" in column) \
                    or "rate" in column or "relative" in column:
                continue
            error = [float(v) for v in table[column]]
            name = f"{label}: {column}"
            by_h.loglog(h, error, "o-", label=name)
            if "wall time [s]" in table:
                by_time.loglog([float(v) for v in table["wall time [s]"]],
                               error, "o-", label=name)
    for slope, style in ((1, "k--"), (2 / 3, "k:")):
        x0 = 0.5
        y0 = by_h.get_ylim()[1] / 2
        by_h.loglog([x0 / 64, x0], [y0 / 64 ** slope, y0], style, lw=0.8,
                    label=f"slope {slope:.2g}")
    by_h.set_xlabel("h")
    by_h.set_ylabel("error")
    by_h.legend(fontsize=7)
    by_time.set_xlabel("wall time of the run [s]")
    by_time.set_ylabel("error")
    by_time.legend(fontsize=7)
    figure.savefig(output, dpi=110)


if __name__ == "__main__":
    main()
