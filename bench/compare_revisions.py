#!/usr/bin/env python3
"""Wall time of a scene as shipped, this checkout against an older
revision, measured in one run: the two programs run in turn, A B A B ...,
and the ratio is taken pair by pair, so that a drift of the machine's speed
between pairs cancels.

    python3 bench/compare_revisions.py REV [--scene prm/barboteu2015.prm]
        [--pairs 9] [--old-binary PATH] [--new-binary PATH] [--out FILE]

REV is built in Release in a git worktree under build-bench-REV/ (or
--old-binary names a program built from it); this checkout is built in
build-bench/ (or --new-binary). Each run writes into its own temporary
output directory, with the scene's own entries otherwise. Printed: the
machine, the median, smallest and largest wall time of each, and the
median ratio new/old with its range.
"""
import argparse
import os
import platform
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def build(source, build_dir):
    subprocess.run(["cmake", "-S", source, "-B", build_dir,
                    "-DCMAKE_BUILD_TYPE=Release"],
                   check=True, stdout=subprocess.DEVNULL)
    subprocess.run(["cmake", "--build", build_dir, "-j2", "--target",
                    "contact"], check=True, stdout=subprocess.DEVNULL)
    return os.path.join(build_dir, "contact")


def old_program(revision):
    tree = os.path.join(ROOT, "build-bench-" + revision)
    if not os.path.isdir(tree):
        subprocess.run(["git", "-C", ROOT, "worktree", "add", "--detach",
                        tree, revision], check=True,
                       stdout=subprocess.DEVNULL)
    return build(tree, os.path.join(tree, "build"))


def wall_time(program, scene, directory):
    start = time.perf_counter()
    subprocess.run([program, "--set", "Output/Output directory=" + directory,
                    scene], check=True, stdout=subprocess.DEVNULL,
                   stderr=subprocess.DEVNULL)
    return time.perf_counter() - start


def machine():
    cpu = "unknown CPU"
    with open("/proc/cpuinfo") as info:
        for line in info:
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    return "Machine: {}, {} cores, Linux {}, load average {:.2f} at the start".format(
        cpu, os.cpu_count(), platform.release(), os.getloadavg()[0])


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("revision")
    parser.add_argument("--scene", default="prm/barboteu2015.prm")
    parser.add_argument("--pairs", type=int, default=9)
    parser.add_argument("--old-binary")
    parser.add_argument("--new-binary")
    parser.add_argument("--out")
    arguments = parser.parse_args()

    old = arguments.old_binary or old_program(arguments.revision)
    new = arguments.new_binary or build(ROOT, os.path.join(ROOT, "build-bench"))
    scene = os.path.join(ROOT, arguments.scene)
    lines = [machine()]
    with tempfile.TemporaryDirectory() as scratch:
        times = {"old": [], "new": []}
        # One run of each first, not counted (caches, the page cache of the
        # mesh and the libraries).
        for name, program in (("old", old), ("new", new)):
            wall_time(program, scene, os.path.join(scratch, name))
        for _ in range(arguments.pairs):
            for name, program in (("old", old), ("new", new)):
                times[name].append(
                    wall_time(program, scene, os.path.join(scratch, name)))
    ratios = [n / o for n, o in zip(times["new"], times["old"])]
    lines.append("Scene {} as shipped, {} pairs, wall time [s] median (min - max):".format(
        arguments.scene, arguments.pairs))
    for name, label in (("old", arguments.revision), ("new", "this checkout")):
        values = times[name]
        lines.append("  {}: {:.3f} ({:.3f} - {:.3f})".format(
            label, statistics.median(values), min(values), max(values)))
    lines.append("  ratio this checkout / {}: {:.3f} ({:.3f} - {:.3f})".format(
        arguments.revision, statistics.median(ratios), min(ratios),
        max(ratios)))
    text = "\n".join(lines)
    print(text)
    if arguments.out:
        with open(arguments.out, "w") as out:
            out.write(text + "\n")


if __name__ == "__main__":
    sys.exit(main())
