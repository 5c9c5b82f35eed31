#!/usr/bin/env python3
"""Wall and CPU time of each stage of `semimesh run`, and the peak memory: figures that stay
comparable on a loaded machine (wall clock does not: it grows with the load, CPU time barely).

Runs SEMIMESH run CONFIG -o OUT --log-json [--set ...], reads its stage events as they come and
samples the process's CPU time (/proc/PID/stat utime + stime: all threads; + cutime + cstime: the
children it has waited for, e.g. the far field's TetGen process) at each stage's start and end; the
peak resident memory and total CPU come from wait4's rusage.

usage: stage_cpu.py SEMIMESH CONFIG OUT [--set key=value ...]
"""
import json
import os
import subprocess
import sys
import time


def cpu_seconds(pid):
    with open(f"/proc/{pid}/stat") as fh:
        fields = fh.read().rsplit(")", 1)[1].split()
    return sum(int(f) for f in fields[11:15]) / os.sysconf("SC_CLK_TCK")  # utime, stime, cutime, cstime


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    exe, config, out, extra = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4:]
    proc = subprocess.Popen([exe, "run", config, "-o", out, "--log-json"] + extra, stdout=subprocess.PIPE,
                            text=True, bufsize=1)
    started, rows = {}, []
    begin = time.monotonic()
    for line in proc.stdout:
        try:
            event = json.loads(line)
        except ValueError:
            continue
        kind = event.get("event")
        if kind == "stage_started":
            started[event["stage"]] = cpu_seconds(proc.pid)
        elif kind == "stage_finished":
            rows.append((event["stage"], event["seconds"], cpu_seconds(proc.pid) - started.pop(event["stage"])))
    _, status, usage = os.wait4(proc.pid, 0)
    wall = time.monotonic() - begin
    print(f"{'stage':<14} {'wall s':>9} {'CPU s':>9}")
    for name, seconds, cpu in rows:
        print(f"{name:<14} {seconds:9.2f} {cpu:9.2f}")
    print(f"{'total':<14} {wall:9.2f} {usage.ru_utime + usage.ru_stime:9.2f}")
    print(f"peak RSS {usage.ru_maxrss / 1024:.0f} MB, exit status {os.waitstatus_to_exitcode(status)}, "
          f"load average {os.getloadavg()[0]:.1f}")


if __name__ == "__main__":
    main()
