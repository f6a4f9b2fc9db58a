#!/usr/bin/env python3
"""What the VTU output costs: the paper's scene as shipped
(prm/barboteu2015.prm with all its settings: its VTU every 8 steps and at
the report times, its friction method, progress lines and timings) against
the same run with 'Output/VTU interval = 0', each run --repeats times,
alternating, in one invocation of this script. Both runs write into a
temporary directory ('Output/Output directory').

    python3 bench/output.py [--repeats 15] [--out bench/output.md] [--no-profile]

Measures the wall time and the CPU time (user + system of the process and
all its threads, from the operating system's account of the finished child)
of every run. Prints the machine facts, every time, the medians and the
ratio of the medians with output to without in both measures, the number
and size of the files the output wrote.

Then, if valgrind is installed, where the output's time goes: the
instructions (callgrind) of a short run of the same scene ('Time/End
time = 0.25') with and without the output, their ratio, and those of the
output's parts. The instructions, unlike the times, do not depend on what
else the machine runs. Their ratio in this short run understates that of
the whole scene: the setup (mesh, factorization of K) is a larger part of
the short run without output than of the whole one. Everything printed is
measured in this run.
"""
import argparse
import os
import re
import resource
import shutil
import statistics
import subprocess
import tempfile

from run import ROOT, build, machine, run


def cpu_seconds():
    """User + system time of the finished children of this script."""
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def measure(contact, prm, sets):
    """Wall and CPU seconds of one run of contact."""
    before = cpu_seconds()
    _, wall, _ = run(contact, prm, sets)
    return wall, cpu_seconds() - before


def vtu_files(directory):
    """The number of .vtu, .pvtu and .pvd files in directory and their
    total size in bytes."""
    counts = {".vtu": 0, ".pvtu": 0, ".pvd": 0}
    size = 0
    for name in os.listdir(directory):
        extension = os.path.splitext(name)[1]
        if extension in counts:
            counts[extension] += 1
            size += os.path.getsize(os.path.join(directory, name))
    return counts, size


def table(times):
    lines = ["| run | wall times [s] | median wall [s] | CPU times [s] "
             "| median CPU [s] |", "|---|---|---|---|---|"]
    for label, runs in times.items():
        walls = [wall for wall, _ in runs]
        cpus = [cpu for _, cpu in runs]
        lines.append(f"| {label} | {', '.join(f'{w:.2f}' for w in walls)} | "
                     f"{statistics.median(walls):.2f} | "
                     f"{', '.join(f'{c:.2f}' for c in cpus)} | "
                     f"{statistics.median(cpus):.2f} |")
    return lines


# deal.II's function that compresses, encodes and writes a VTU file.
WRITER = "write_vtu_main<2, 2>("

# The parts of an output, as (label, a text that only the part's function
# has in callgrind_annotate's listing).
PARTS = [
    ("the output thread (everything below)",
     "VtuOutput<2>::write_vtu_piece("),
    ("- DataOut::build_patches (the first output on a mesh)",
     "DataOut<2, 2>::build_patches(dealii::Mapping"),
    ("- refilling the patches (the later outputs)",
     "VtuOutput<2>::refresh_patches("),
    ("  - where their values come from (once per mesh)",
     "VtuOutput<2>::find_patch_sources("),
    ("- deal.II's write_vtu", WRITER),
    ("  - zlib compression (compress2)", ":compress2 ["),
    ("  - base64 encoding", "encode_base64[abi:cxx11](std::vector<unsigned char"),
    ("the time loop's thread: copies of the fields, the stress",
     "VtuOutput<2>::write_vtu() ["),
    ("- the cell averages of the stress", "VtuOutput<2>::cell_average_stress("),
    ("  - the averages of the shape functions' gradients (once per mesh)",
     "VtuOutput<2>::find_mean_gradients("),
]


def instructions(contact, prm, sets, directory):
    """callgrind's inclusive instruction counts of one run: a dict from
    the texts of PARTS (and "total") to counts."""
    out = os.path.join(directory, "callgrind.out")
    subprocess.run(["valgrind", "--tool=callgrind",
                    f"--callgrind-out-file={out}", contact]
                   + sum((["--set", entry] for entry in sets), []) + [prm],
                   check=True, stdout=subprocess.DEVNULL,
                   stderr=subprocess.DEVNULL)
    listing = subprocess.run(["callgrind_annotate", "--inclusive=yes", out],
                             check=True, capture_output=True, text=True).stdout
    counts = {}
    for line in listing.splitlines():
        match = re.match(r"\s*([\d,]+) \(\s*[\d.]+%\)\s+(.*)", line)
        if not match:
            continue
        count = int(match.group(1).replace(",", ""))
        if "PROGRAM TOTALS" in match.group(2):
            counts.setdefault("total", count)
        for _, text in PARTS:
            if text in match.group(2):
                counts.setdefault(text, count)
    return counts


def profile(contact, prm):
    """Where the output's time goes, in instructions per output."""
    if not shutil.which("valgrind"):
        return ["", "valgrind is not installed: no profile of the output."]
    sets = ["Time/End time=0.25"]
    with tempfile.TemporaryDirectory() as directory:
        without = instructions(
            contact, prm, sets + ["Output/VTU interval=0",
                                  f"Output/Output directory={directory}/0"],
            directory)
        counts = instructions(
            contact, prm, sets + [f"Output/Output directory={directory}/8"],
            directory)
        outputs = vtu_files(os.path.join(directory, "8"))[0][".vtu"]
    added = counts["total"] - without["total"]
    lines = ["", "## Where the time goes",
             "",
             f"callgrind, the scene up to t = 0.25 ({outputs} outputs; "
             "instructions, which leave out what the processor waits for): "
             f"{without['total'] / 1e6:.0f} M instructions without the "
             f"output, {counts['total'] / 1e6:.0f} M with it "
             f"({counts['total'] / without['total']:.2f} times); the output "
             f"adds {added / 1e6:.0f} M, {added / outputs / 1e6:.0f} M per "
             "output, of which (inclusive counts, all outputs):",
             "",
             "| part | M instructions | share of what the output adds |",
             "|---|---|---|"]
    for label, text in PARTS:
        count = counts.get(text, 0)
        lines.append(f"| {label} | {count / 1e6:.0f} | "
                     f"{100 * count / added:.0f} % |")
    ratio = counts["total"] / without["total"]
    writer = counts.get(WRITER, 0)
    lines += ["",
              f"At most 1.3 times in instructions (this short run, whose "
              "setup weighs more than in the whole scene's run): "
              f"{'yes' if ratio <= 1.3 else 'no'} ({ratio:.2f}).",
              "",
              "deal.II's write_vtu alone (the same file needs the same "
              "compression and encoding) makes the short run "
              f"{1 + writer / without['total']:.2f} times the instructions "
              "of the run without output."]
    return lines


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--repeats", type=int, default=15)
    parser.add_argument("--out", default=os.path.join(ROOT, "bench", "output.md"))
    parser.add_argument("--no-profile", dest="profile", action="store_false",
                        help="skip the callgrind profile")
    arguments = parser.parse_args()
    contact = build()
    prm = os.path.join(ROOT, "prm", "barboteu2015.prm")
    lines = [f"Machine: {machine()}", ""]
    variants = {"as shipped": [], "VTU interval = 0": ["Output/VTU interval=0"]}
    runs = {label: [] for label in variants}
    with tempfile.TemporaryDirectory() as directory:
        for repeat in range(arguments.repeats):
            for index, (label, sets) in enumerate(variants.items()):
                out = os.path.join(directory, f"{index}-{repeat}")
                runs[label].append(measure(
                    contact, prm, sets + [f"Output/Output directory={out}"]))
        counts, size = vtu_files(os.path.join(directory, "0-0"))
    lines += table(runs)
    medians = [[statistics.median(x[i] for x in results)
                for results in runs.values()] for i in (0, 1)]
    lines += ["",
              f"The output wrote {counts['.vtu']} .vtu, {counts['.pvtu']} "
              f".pvtu and {counts['.pvd']} .pvd files, {size / 1e6:.1f} MB.",
              f"With it the run costs {medians[0][0] / medians[0][1]:.2f} "
              f"times the run without in wall time and "
              f"{medians[1][0] / medians[1][1]:.2f} times in CPU time "
              "(medians)."]
    for measure_name, (with_output, without) in zip(("wall", "CPU"), medians):
        ratio = with_output / without
        lines.append(f"At most 1.3 times in {measure_name} time: "
                     f"{'yes' if ratio <= 1.3 else 'no'} ({ratio:.2f}).")
    if arguments.profile:
        lines += profile(contact, prm)
    text = "\n".join(lines) + "\n"
    print(text)
    with open(arguments.out, "w") as out:
        out.write("# The cost of the VTU output\n\n"
                  "Written by `python3 bench/output.py` (see its docstring).\n\n"
                  + text)


if __name__ == "__main__":
    main()
