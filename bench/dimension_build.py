#!/usr/bin/env python3
"""Build time of the program for CONTACT_DIMENSIONS = "2;3" (the default),
"2" and "3", measured in one run on this machine: each is configured in a
fresh directory under build-bench-dimensions/ and built with -j2 (target
`contact`, Release), without ccache, one after the other.

    python3 bench/dimension_build.py [--jobs 2]

Printed: the machine, the wall time of each build and its ratio to the
default's.
"""
import argparse
import os
import shutil
import subprocess
import time

from compare_revisions import machine

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def build_time(dimensions, jobs):
    tree = os.path.join(ROOT, "build-bench-dimensions",
                        dimensions.replace(";", "_"))
    shutil.rmtree(tree, ignore_errors=True)
    environment = dict(os.environ, CCACHE_DISABLE="1")
    subprocess.run(["cmake", "-S", ROOT, "-B", tree,
                    "-DCMAKE_BUILD_TYPE=Release",
                    "-DCONTACT_DIMENSIONS=" + dimensions],
                   check=True, stdout=subprocess.DEVNULL, env=environment)
    start = time.perf_counter()
    subprocess.run(["cmake", "--build", tree, "-j%d" % jobs, "--target",
                    "contact"], check=True, stdout=subprocess.DEVNULL,
                   stderr=subprocess.DEVNULL, env=environment)
    return time.perf_counter() - start


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--jobs", type=int, default=2)
    arguments = parser.parse_args()
    print(machine())
    print("Build of `contact` (Release, -j%d, no ccache), wall time:"
          % arguments.jobs)
    times = {}
    for dimensions in ["2;3", "2", "3"]:
        times[dimensions] = build_time(dimensions, arguments.jobs)
        print("  CONTACT_DIMENSIONS=\"%s\": %.0f s (%.2f of \"2;3\")" % (
            dimensions, times[dimensions], times[dimensions] / times["2;3"]),
            flush=True)


if __name__ == "__main__":
    main()
