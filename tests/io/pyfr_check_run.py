"""`semimesh run` for PyFR, then PyFR's reader rules (pyfr_rules.py) on the MSH it wrote.

Runs SEMIMESH run CONFIG -o WORKDIR with output.target = "pyfr" and ASCII MSH 4.1 (plus any
--set), requires exit 0 (our certification found no invalid element) and every rule of PyFR's
importer met by WORKDIR/BASENAME.msh.

usage: pyfr_check_run.py --exe SEMIMESH --config CONFIG --workdir DIR --basename NAME [--set key=value ...]
"""
import argparse
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import pyfr_rules


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    ap.add_argument("--config", required=True)
    ap.add_argument("--workdir", required=True)
    ap.add_argument("--basename", required=True)
    ap.add_argument("--set", action="append", default=[])
    a = ap.parse_args()
    shutil.rmtree(a.workdir, ignore_errors=True)
    cmd = [a.exe, "run", a.config, "-o", a.workdir, "--set", 'output.target="pyfr"',
           "--set", 'output.formats=["msh41-ascii"]', "--set", f'output.basename="{a.basename}"']
    for s in a.set:
        cmd += ["--set", s]
    run = subprocess.run(cmd, capture_output=True, text=True)
    print(run.stdout[-2500:])
    if run.returncode != 0:
        print(run.stderr[-3000:])
        sys.exit(f"semimesh run failed with code {run.returncode}")
    msh = os.path.join(a.workdir, a.basename + ".msh")
    bad = pyfr_rules.check(msh)
    for b in bad:
        print("PyFR refuses:", b)
    if bad:
        sys.exit(f"{msh}: {len(bad)} violation(s) of PyFR's reader rules")
    print(f"{msh}: PyFR's reader rules met")


if __name__ == "__main__":
    main()
