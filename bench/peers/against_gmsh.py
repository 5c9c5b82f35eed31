#!/usr/bin/python3
"""The paper's case against Gmsh's boundary-layer wing, back to back (issue 25's headline figure:
our time per element over Gmsh's). Each round runs `semimesh run` on the paper's case at order 3
writing binary MSH 4.1 only, then gmsh_bl_wing.py (Gmsh's own wing at order 3 with fast curving,
its binary MSH 4.1 written), one process at a time. Per element: our wall time over our element
count (report.json) against Gmsh's over its count (its own printout).

Two Gmsh figures, both printed: its meshing alone (generate, setOrder and the fast curving, as
gmsh_bl_wing.py's "total"), and that plus the write of its mesh file ("total with write"). Ours is
the process's wall time from start to exit: loading, meshing, checking, writing the mesh file and
the report. Against Gmsh with its write both sides have written their mesh; against its meshing
alone ours carries its write and its checks (a conservative ratio).

usage: against_gmsh.py SEMIMESH [--rounds N] [--config FILE] [--order P] [--work DIR]
       [--lock FILE] [--python EXE]
  SEMIMESH: the semimesh executable
  --rounds N: rounds (default 6); the figures are medians and ranges over them
  --config FILE: our case (default examples/naca0012_wing.toml, the paper's)
  --order P: the order of both meshes (default 3)
  --work DIR: where both write their files (default a temporary folder, removed)
  --lock FILE: hold this file's lock (flock) around each run, so that other benchmarks that take it
               do not run beside (default: none)
  --python EXE: the Python with Gmsh's module for gmsh_bl_wing.py (default /usr/bin/python3,
                Debian's python3-gmsh)
"""
import argparse
import fcntl
import json
import os
import re
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))


class Lock:
    """flock on a file for the duration of one run (none when no path is given)."""

    def __init__(self, path):
        self.path, self.file = path, None

    def __enter__(self):
        if self.path:
            self.file = open(self.path, "a")
            fcntl.flock(self.file, fcntl.LOCK_EX)

    def __exit__(self, *exc):
        if self.file:
            fcntl.flock(self.file, fcntl.LOCK_UN)
            self.file.close()


def children_cpu():
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime, usage.ru_stime


def run_ours(args, out):
    """(wall s, user s, sys s, elements) of one semimesh run; exits with its message if it fails."""
    shutil.rmtree(out, ignore_errors=True)
    command = [args.semimesh, "run", args.config, "-o", out, "--set", "highorder.order=%d" % args.order,
               "--set", 'output.formats=["msh41"]']
    user0, sys0 = children_cpu()
    start = time.monotonic()
    done = subprocess.run(command, cwd=ROOT, capture_output=True, text=True)
    wall = time.monotonic() - start
    user1, sys1 = children_cpu()
    if done.returncode != 0:
        sys.exit("semimesh failed (exit %d): %s\n%s" % (done.returncode, " ".join(command), done.stderr[-2000:]))
    with open(os.path.join(out, "report.json")) as f:
        elements = json.load(f)["elements"]
    return wall, user1 - user0, sys1 - sys0, elements


def run_gmsh(args, path):
    """(meshing s, meshing and write s, elements) of one gmsh_bl_wing.py run."""
    command = [args.python, os.path.join(HERE, "gmsh_bl_wing.py"), "--order", str(args.order), "--no-check",
               "--write", path]
    done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit("gmsh_bl_wing.py failed (exit %d):\n%s" % (done.returncode, done.stderr[-2000:]))
    text = done.stdout
    elements = re.search(r"^volume elements \(order \d+\): (\d+)", text, re.M)
    total = re.search(r"^total\s+([0-9.]+)", text, re.M)
    with_write = re.search(r"total with write ([0-9.]+) s", text)
    if not (elements and total and with_write):
        sys.exit("gmsh_bl_wing.py printed no element count or total:\n" + text[-2000:])
    os.remove(path)
    return float(total.group(1)), float(with_write.group(1)), int(elements.group(1))


def spread(values, digits=3):
    return "median %.*f (%.*f-%.*f)" % (digits, statistics.median(values), digits, min(values), digits, max(values))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("semimesh")
    parser.add_argument("--rounds", type=int, default=6)
    parser.add_argument("--config", default=os.path.join(ROOT, "examples", "naca0012_wing.toml"))
    parser.add_argument("--order", type=int, default=3)
    parser.add_argument("--work")
    parser.add_argument("--lock")
    parser.add_argument("--python", default="/usr/bin/python3")
    args = parser.parse_args()
    if args.rounds < 1:
        sys.exit("--rounds must be >= 1")
    args.semimesh = os.path.abspath(args.semimesh)
    args.config = os.path.abspath(args.config)
    work = args.work or tempfile.mkdtemp(prefix="against_gmsh.")
    os.makedirs(work, exist_ok=True)
    print("%5s %10s %8s %8s %10s %10s %14s %12s %5s %5s" % ("round", "ours s", "user s", "sys s", "ours el", "Gmsh s",
                                                           "with write s", "Gmsh el", "ratio", "w. write"), flush=True)
    ratios, ratios_with_write, ours, gmsh, cpu = [], [], [], [], []
    try:
        for r in range(args.rounds):
            with Lock(args.lock):
                wall, user, system, our_elements = run_ours(args, os.path.join(work, "ours"))
            with Lock(args.lock):
                meshing, with_write, gmsh_elements = run_gmsh(args, os.path.join(work, "gmsh.msh"))
            ratio = (wall / our_elements) / (meshing / gmsh_elements)
            ratio_with_write = (wall / our_elements) / (with_write / gmsh_elements)
            ratios.append(ratio), ratios_with_write.append(ratio_with_write)
            ours.append(wall), gmsh.append(meshing), cpu.append(user + system)
            print("%5d %10.2f %8.2f %8.2f %10d %10.2f %14.2f %12d %5.3f %5.3f" % (
                r + 1, wall, user, system, our_elements, meshing, with_write, gmsh_elements, ratio, ratio_with_write),
                flush=True)
    finally:
        if not args.work:
            shutil.rmtree(work, ignore_errors=True)
    print("ours: wall %s s, CPU (user + sys) %s s" % (spread(ours, 2), spread(cpu, 2)))
    print("Gmsh meshing: %s s" % spread(gmsh, 2))
    print("per-element time, ours over Gmsh's meshing: %s" % spread(ratios))
    print("per-element time, ours over Gmsh's meshing and write: %s" % spread(ratios_with_write))


if __name__ == "__main__":
    main()
