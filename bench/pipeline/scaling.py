#!/usr/bin/env python3
"""Time and memory per element of each stage of `semimesh run` as the paper's case grows (issue 25,
point 5): the paper's geometry (examples/naca0012_wing.toml) with every length of its sizing scaled
by one factor s (sizing.max_size, min_size, le_size, te_size, farfield.box_size, wall_size; the
curvature's segments per radian and the wake's streamwise cells divided by s, the wake's growth
raised to the power s, so that its cells shrink by s too: with the growth kept, 117 cells growing by
1.15 over the wake's 2 chords start with a cell of 2.4e-8, which TetGen merges), at each order asked
for. The element count goes as s^-k with k between 1 and 3 (the far field is graded from the
body's sizes, so its tets follow the surface's s^-2 more than the box's s^-3): k is fitted from the
paper's case (s = 1) and the last run before each target's s is chosen, and the table gives the
count reached.

For each run: per stage, CPU microseconds per element and the largest resident memory in bytes per
element (bench/pipeline/stage_cpu.py's measurement); then, per order, each stage's CPU time per
element at the largest count over the one at the smallest (1.0: linear; the issue asks for <= 1.3).

usage: scaling.py SEMIMESH OUT [--config CONFIG] [--targets 1e5,1e6,4e6,1e7] [--orders 1,3]
"""
import argparse
import json
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from stage_cpu import measure

PAPER_ELEMENTS = 523180  # the paper's case at s = 1 (any order)
FIRST_EXPONENT = 1.3  # measured between 1e5 and 1e6 elements (order 1)
SIZES = {"sizing.max_size": 2.0, "sizing.min_size": 0.005, "sizing.le_size": 0.02, "sizing.te_size": 0.01,
         "farfield.box_size": 2.0, "farfield.wall_size": 1.0}
PER_LENGTH = {"sizing.curvature_segments": 4.0}
CELLS = {"wake.layers": 12}
GROWTHS = {"wake.growth": 1.15}


def settings(s, order):
    sets = [f"highorder.order={order}", 'output.formats=["msh41"]']
    sets += [f"{k}={v * s:.6g}" for k, v in SIZES.items()]
    sets += [f"{k}={v / s:.6g}" for k, v in PER_LENGTH.items()]
    sets += [f"{k}={max(1, round(v / s))}" for k, v in CELLS.items()]
    sets += [f"{k}={v ** s:.6g}" for k, v in GROWTHS.items()]
    return [a for kv in sets for a in ("--set", kv)]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("exe")
    ap.add_argument("out")
    ap.add_argument("--config", default=os.path.join(os.path.dirname(__file__), "..", "..", "examples",
                                                      "naca0012_wing.toml"))
    # 4e6 between: the fit from 10^6 alone overshoots 10^7 (s = 0.081, ~2.5e7 elements: more
    # memory than a 24 GB machine has for TetGen's process).
    ap.add_argument("--targets", default="1e5,1e6,4e6,1e7")
    ap.add_argument("--orders", default="1,3")
    a = ap.parse_args()
    summary = []
    for order in [int(o) for o in a.orders.split(",")]:
        runs = []
        known, exponent = (1.0, PAPER_ELEMENTS), FIRST_EXPONENT  # (s, elements) nearest the next target
        for target in [float(t) for t in a.targets.split(",")]:
            s = known[0] * (known[1] / target) ** (1.0 / exponent)
            out = os.path.join(a.out, f"order{order}_{target:.0e}")
            rows, wall, cpu, peak, status = measure(a.exe, a.config, out, settings(s, order))
            if status != 0:
                print(f"order {order}, target {target:.0e} (s = {s:.3f}): semimesh exited with {status}")
                continue
            with open(os.path.join(out, "report.json")) as fh:
                elements = json.load(fh)["elements"]
            runs.append((elements, rows))
            if abs(math.log(known[0] / s)) > 0.05:
                exponent = max(1.0, min(3.0, math.log(elements / known[1]) / math.log(known[0] / s)))
            known = (s, elements)
            print(f"\norder {order}, s = {s:.3f}: {elements:,} elements, {wall:.1f} s wall, {cpu:.1f} s CPU, "
                  f"peak {peak:,.0f} MB = {peak * 2**20 / elements:,.0f} bytes/element, load {os.getloadavg()[0]:.1f}")
            print(f"  {'stage':<14} {'wall s':>8} {'CPU s':>8} {'CPU us/el':>10} {'RSS B/el':>9}")
            for name, seconds, stage_cpu, rss in rows:
                print(f"  {name:<14} {seconds:8.2f} {stage_cpu:8.2f} {stage_cpu * 1e6 / elements:10.2f} "
                      f"{rss * 2**20 / elements:9.0f}")
            for f in os.listdir(out):  # the meshes are not kept: 10^7 elements write gigabytes
                if f.endswith(".msh"):
                    os.remove(os.path.join(out, f))
        if len(runs) >= 2:
            (n0, first), (n1, last) = runs[0], runs[-1]
            small = {name: cpu * 1e6 / n0 for name, _, cpu, _ in first}
            summary.append((order, n0, n1, [(name, (cpu * 1e6 / n1) / small[name]) for name, _, cpu, _ in last
                                             if small.get(name, 0) > 0.01]))
    for order, n0, n1, ratios in summary:
        print(f"\norder {order}: CPU time per element at {n1:,} over at {n0:,} elements")
        for name, ratio in ratios:
            print(f"  {name:<14} {ratio:6.2f}{'' if ratio <= 1.3 else '   (> 1.3: superlinear)'}")


if __name__ == "__main__":
    main()
