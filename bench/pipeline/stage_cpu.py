#!/usr/bin/env python3
"""Wall and CPU time of each stage of `semimesh run`, and the peak memory: figures that stay
comparable on a loaded machine (wall clock does not: it grows with the load, CPU time barely).

Runs SEMIMESH run CONFIG -o OUT --log-json [--set ...], reads its stage events as they come and
samples the process's CPU time (/proc/PID/stat utime + stime: all threads; + cutime + cstime: the
children it has waited for, e.g. the far field's TetGen process) at each stage's start and end; the
peak resident memory and total CPU come from wait4's rusage. The largest resident memory seen in
each stage comes from /proc/PID/status (VmRSS, sampled every 0.2 s): where the peak is.

usage: stage_cpu.py SEMIMESH CONFIG OUT [--set key=value ...]
"""
import json
import os
import subprocess
import sys
import threading
import time


def cpu_seconds(pid):
    with open(f"/proc/{pid}/stat") as fh:
        fields = fh.read().rsplit(")", 1)[1].split()
    return sum(int(f) for f in fields[11:15]) / os.sysconf("SC_CLK_TCK")  # utime, stime, cutime, cstime


def resident_mb(pid):
    try:
        with open(f"/proc/{pid}/status") as fh:
            for line in fh:
                if line.startswith("VmRSS:"):
                    return int(line.split()[1]) / 1024
    except OSError:
        pass
    return 0.0


def sample_resident(pid, current, largest, stop):
    """largest[stage] = the most VmRSS seen while current[0] was that stage, until stop is set."""
    while not stop.is_set():
        mb = resident_mb(pid)
        largest[current[0]] = max(largest.get(current[0], 0.0), mb)
        stop.wait(0.2)


def measure(exe, config, out, extra):
    """Runs SEMIMESH run CONFIG -o OUT --log-json EXTRA. Returns rows [(stage, wall s, CPU s, largest
    RSS MB)], the total wall and CPU seconds, the peak RSS in MB and the exit status."""
    proc = subprocess.Popen([exe, "run", config, "-o", out, "--log-json"] + extra, stdout=subprocess.PIPE,
                            text=True, bufsize=1)
    started, finished = {}, []
    current, largest, stop = ["(between stages)"], {}, threading.Event()
    sampler = threading.Thread(target=sample_resident, args=(proc.pid, current, largest, stop), daemon=True)
    sampler.start()
    begin = time.monotonic()
    for line in proc.stdout:
        try:
            event = json.loads(line)
        except ValueError:
            continue
        kind = event.get("event")
        if kind == "stage_started":
            started[event["stage"]] = cpu_seconds(proc.pid)
            current[0] = event["stage"]
        elif kind == "stage_finished":
            finished.append((event["stage"], event["seconds"], cpu_seconds(proc.pid) - started.pop(event["stage"])))
            current[0] = "(between stages)"
    stop.set()
    sampler.join()
    _, status, usage = os.wait4(proc.pid, 0)
    wall = time.monotonic() - begin
    rows = [(name, seconds, cpu, largest.get(name, 0.0)) for name, seconds, cpu in finished]
    return rows, wall, usage.ru_utime + usage.ru_stime, usage.ru_maxrss / 1024, os.waitstatus_to_exitcode(status)


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    rows, wall, cpu, peak, status = measure(sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4:])
    print(f"{'stage':<14} {'wall s':>9} {'CPU s':>9} {'RSS MB':>9}")
    for name, seconds, stage_cpu, rss in rows:
        print(f"{name:<14} {seconds:9.2f} {stage_cpu:9.2f} {rss:9.0f}")
    print(f"{'total':<14} {wall:9.2f} {cpu:9.2f}")
    print(f"peak RSS {peak:.0f} MB, exit status {status}, load average {os.getloadavg()[0]:.1f}")


if __name__ == "__main__":
    main()
