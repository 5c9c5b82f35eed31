#!/usr/bin/env python3
"""Each stage's CPU seconds on the main thread, on the process's other live threads and in waited-for
children (the far field's TetGen), from /proc at the stage events of `semimesh run --log-json`: the
main thread's share bounds a stage's serial path (where the other core idles). Threads that end
inside a stage (std::async) are not in `others`; stage_cpu.py's totals include them.

usage: stage_threads.py SEMIMESH CONFIG OUT [--set key=value ...]
"""
import json
import os
import subprocess
import sys
import time

TICKS = os.sysconf("SC_CLK_TCK")


def thread_cpu(pid):
    """{tid: CPU s} of pid's live threads, and 'children': its waited-for children's CPU s."""
    out = {}
    try:
        for tid in os.listdir(f"/proc/{pid}/task"):
            try:
                with open(f"/proc/{pid}/task/{tid}/stat") as fh:
                    fields = fh.read().rsplit(")", 1)[1].split()
                out[int(tid)] = (int(fields[11]) + int(fields[12])) / TICKS
            except OSError:
                pass
        with open(f"/proc/{pid}/stat") as fh:
            fields = fh.read().rsplit(")", 1)[1].split()
        out["children"] = (int(fields[13]) + int(fields[14])) / TICKS
    except OSError:
        pass
    return out


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    exe, config, out = sys.argv[1:4]
    proc = subprocess.Popen([exe, "run", config, "-o", out, "--log-json"] + sys.argv[4:], stdout=subprocess.PIPE,
                            text=True, bufsize=1)
    started = {}
    print(f"{'stage':<14}{'wall s':>8}{'main s':>8}{'others s':>10}{'children s':>12}")
    for line in proc.stdout:
        try:
            event = json.loads(line)
        except ValueError:
            continue
        if event.get("event") == "stage_started":
            started[event["stage"]] = (time.monotonic(), thread_cpu(proc.pid))
        elif event.get("event") == "stage_finished":
            begin, before = started.pop(event["stage"])
            after = thread_cpu(proc.pid)
            main_s = after.get(proc.pid, 0.0) - before.get(proc.pid, 0.0)
            children = after.get("children", 0.0) - before.get("children", 0.0)
            others = sum(v - before.get(t, 0.0) for t, v in after.items() if t not in (proc.pid, "children"))
            print(f"{event['stage']:<14}{time.monotonic() - begin:8.2f}{main_s:8.2f}{others:10.2f}{children:12.2f}",
                  flush=True)
    sys.exit(os.waitstatus_to_exitcode(os.wait4(proc.pid, 0)[1]))


if __name__ == "__main__":
    main()
