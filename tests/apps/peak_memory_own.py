"""The report's peak memory is the run's own, whatever started it.

  peak_memory_own.py SEMIMESH CONFIG WORKDIR

Holds 600 MB (touched) while it runs `semimesh run CONFIG` (a coarse case of ~100 MB) and fails
unless report.json's peak_memory_mb is below 400: Linux carries getrusage's ru_maxrss over an exec
from the forking process, so a run started by a large process used to report that process's size.
"""
import json
import os
import subprocess
import sys


def main():
    exe, config, workdir = sys.argv[1:4]
    ballast = bytearray(600 * 1024 * 1024)
    for i in range(0, len(ballast), 4096):
        ballast[i] = 1  # resident, not only reserved
    out = os.path.join(workdir, "out")
    done = subprocess.run([exe, "run", config, "-o", out, "--quiet"], capture_output=True, text=True)
    if done.returncode != 0:
        print("FAIL: run exited %d\n%s" % (done.returncode, done.stderr))
        return 1
    with open(os.path.join(out, "report.json")) as f:
        peak = json.load(f)["peak_memory_mb"]
    print("report's peak memory %.0f MB, the parent held %d MB" % (peak, len(ballast) >> 20))
    if not peak < 400:
        print("FAIL: the report counts the parent's memory")
        return 1
    print("ok")
    return 0


if __name__ == "__main__":
    sys.exit(main())
