"""Runs the semimesh CLI once and checks its exit code, stderr and (optionally) its JSON output.

Used by CTest (tests/apps/CMakeLists.txt) with Debian's /usr/bin/python3; standard library only.

  cli_check.py --exe PATH [--exit N] [--stderr-has TEXT]... [--stderr-is TEXT]
               [--stdout-has TEXT]... [--stdout-is TEXT] [--no-stdout] [--json CHECK] [--json-lines]
               [--progress-events STAGE]... [--no-carriage-returns] [--pty] [--write NAME:PATH] -- ARGS...

--write NAME:PATH writes the fixture file NAME (see FIXTURES) to PATH before running.
--json CHECK parses stdout as one JSON object and runs the named check of JSON_CHECKS.
--json-lines parses every stdout line as a JSON object; the last must be the "result" event with
the run's exit code; with --progress-events, every "progress" event must lie inside its stage (after
its stage_started, before its stage_finished), with fractions in [0, 1] that never decrease within
the stage, and each STAGE named must have at least two. --rewrites-lines expects a line rewritten in
place. --no-carriage-returns expects no '\r' byte on stdout (plain output for logs). --pty runs
the command on a pseudo-terminal (script(1)), stdout and stderr then arrive together as stdout.
"""
import argparse
import json
import math
import os
import shlex
import shutil
import subprocess
import sys

# A STEP file that parses but holds only a point: no solid, no face.
POINT_ONLY_STEP = """ISO-10303-21;
HEADER;
FILE_DESCRIPTION(('a single point'),'2;1');
FILE_NAME('point_only.stp','2026-01-01T00:00:00',('semimesh tests'),(''),'','','');
FILE_SCHEMA(('AUTOMOTIVE_DESIGN { 1 0 10303 214 1 1 1 1 }'));
ENDSEC;
DATA;
#1=CARTESIAN_POINT('',(0.,0.,0.));
ENDSEC;
END-ISO-10303-21;
"""

FIXTURES = {
    "point_only_step": POINT_ONLY_STEP,
    "corrupt_step": "ISO-10303-21;\nHEADER;\nthis is not a STEP file at all ((((\n",
    "empty_brep": "",
}

# NACA 0012 blunt (a4 = -0.1015) section area per unit chord^2: 2 * integral of y_t over [0, 1]
# = 10 t (0.2969 * 2/3 - 0.1260 / 2 - 0.3516 / 3 + 0.2843 / 4 - 0.1015 / 5).
NACA0012_SECTION_AREA = 10 * 0.12 * (0.2969 * 2 / 3 - 0.1260 / 2 - 0.3516 / 3 + 0.2843 / 4 - 0.1015 / 5)

NACA_SURFACES = ["upper", "lower", "te_base", "tip", "wall", "box_xmin", "box_xmax", "box_ymin", "box_ymax", "box_zmax"]


def fail(message):
    print("cli_check: FAILED: " + message)
    sys.exit(1)


def expect(condition, message):
    if not condition:
        fail(message)


def common_keys(doc):
    for key, kind in [("backend", str), ("vertices", int), ("curves", int), ("surfaces", int), ("bbox", list),
                      ("closed", bool), ("units", str), ("surface_list", list)]:
        expect(key in doc, "key '%s' missing" % key)
        expect(isinstance(doc[key], kind), "key '%s' is %r, expected %s" % (key, doc[key], kind.__name__))
    expect(len(doc["bbox"]) == 6, "bbox must have 6 numbers")
    expect(all(doc["bbox"][i] < doc["bbox"][i + 3] for i in range(3)), "bbox min must be below max: %r" % doc["bbox"])
    expect(len(doc["surface_list"]) == doc["surfaces"], "surface_list length differs from surfaces")
    for i, s in enumerate(doc["surface_list"]):
        expect(set(s) == {"id", "name", "kind", "area"}, "surface entry keys: %r" % sorted(s))
        expect(s["id"] == i, "surface ids must be 0..n-1 in order")
        expect(s["area"] > 0, "surface %d '%s' has area %r" % (i, s["name"], s["area"]))


def default_wing(doc, backend):
    common_keys(doc)
    expect(doc["backend"] == backend, "backend is %r, expected %r" % (doc["backend"], backend))
    expect(doc["surfaces"] == 10 and doc["curves"] == 21 and doc["vertices"] == 14,
           "counts %d/%d/%d, expected 10 surfaces, 21 curves, 14 vertices" % (doc["surfaces"], doc["curves"], doc["vertices"]))
    expect(doc["closed"] is True, "the default wing in its box is closed")
    expect(doc["units"] == "chord", "units %r" % doc["units"])
    for got, want in zip(doc["bbox"], [-10, -10, 0, 11, 10, 10]):
        expect(abs(got - want) < 1e-9, "bbox %r, expected the default box" % doc["bbox"])
    expect([s["name"] for s in doc["surface_list"]] == NACA_SURFACES, "surface names/order: %r" % doc["surface_list"])
    area = {s["name"]: s["area"] for s in doc["surface_list"]}
    boxes = {"box_xmin": 200, "box_xmax": 200, "box_ymin": 210, "box_ymax": 210, "box_zmax": 420}
    for name, want in boxes.items():
        expect(math.isclose(area[name], want, rel_tol=1e-6), "%s area %r, expected %r" % (name, area[name], want))
    # Trimmed faces: cad-info's documented area accuracy is 1e-3 relative (apps/surface_area.hpp).
    expect(math.isclose(area["tip"], NACA0012_SECTION_AREA, rel_tol=1e-3),
           "tip area %r, expected the NACA 0012 section area %r" % (area["tip"], NACA0012_SECTION_AREA))
    expect(math.isclose(area["wall"], 420 - NACA0012_SECTION_AREA, rel_tol=1e-5),
           "wall area %r, expected 420 minus the root section" % area["wall"])
    # Blunt TE base: thickness 2 y_t(1) = 10 t (0.2969 - 0.1260 - 0.3516 + 0.2843 - 0.1015) times span 3.
    te = 10 * 0.12 * (0.2969 - 0.1260 - 0.3516 + 0.2843 - 0.1015) * 3
    expect(math.isclose(area["te_base"], te, rel_tol=1e-4), "te_base area %r, expected %r" % (area["te_base"], te))
    expect(math.isclose(area["upper"], area["lower"], rel_tol=1e-6), "a symmetric wing has equal skins")
    # The roles found without names are the model's own names for them.
    roles = doc["roles"]
    expect(roles["found"] is True, "roles not found: %r" % roles)
    named = lambda ids: sorted(NACA_SURFACES[i] for i in ids)
    expect(NACA_SURFACES[roles["wall"]] == "wall", "wall %r" % roles["wall"])
    expect(named(roles["body"]) == sorted(["upper", "lower", "te_base", "tip"]), "body %r" % named(roles["body"]))
    expect(named(roles["farfield"]) == sorted(n for n in NACA_SURFACES if n.startswith("box_")), "far field %r" % roles)
    expect(NACA_SURFACES[roles["te_base"]] == "te_base" and named(roles["tip"]) == ["tip"], "te_base, tip %r" % roles)


def step_file(doc, faces, built):
    common_keys(doc)
    expect(doc["backend"] == "occ", "STEP files load with occ, got %r" % doc["backend"])
    expect(doc["surfaces"] == faces, "%d surfaces, expected %d" % (doc["surfaces"], faces))
    expect(doc["units"] != "", "units must be named")
    expect(doc["wall_and_box_built"] == built, "wall_and_box_built %r, expected %r" % (doc["wall_and_box_built"], built))


JSON_CHECKS = {
    "naca_default": lambda d: default_wing(d, "naca"),
    "occ_default": lambda d: default_wing(d, "occ"),
    "nektar_wing": lambda d: step_file(d, 9, False),
    # The body-only M6 as `run` loads it (init's wall plane and box built: 11 faces in the file + 5).
    "onera_m6": lambda d: step_file(d, 16, True),
}


def check_progress_events(events, stages):
    running, last, count = None, {}, {}
    for e in events:
        if e["event"] == "stage_started":
            running = e["stage"]
        elif e["event"] == "stage_finished":
            running = None
        elif e["event"] == "progress":
            stage, fraction = e["stage"], e["fraction"]
            expect(stage == running, "progress event outside its stage: %r (running: %r)" % (e, running))
            expect(isinstance(fraction, (int, float)) and 0 <= fraction <= 1, "fraction outside [0, 1]: %r" % e)
            expect(isinstance(e.get("step"), str), "a progress event names its step: %r" % e)
            expect(fraction >= last.get(stage, 0), "fraction went back in %s: %r after %r" % (stage, fraction, last.get(stage, 0)))
            last[stage] = fraction
            count[stage] = count.get(stage, 0) + 1
    for stage in stages:
        expect(count.get(stage, 0) >= 2, "stage %r has %d progress event(s), expected at least 2 (all: %r)"
               % (stage, count.get(stage, 0), count))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--exe", required=True)
    parser.add_argument("--exit", type=int, default=0)
    parser.add_argument("--stderr-has", action="append", default=[])
    parser.add_argument("--stderr-is")
    parser.add_argument("--stdout-has", action="append", default=[])
    parser.add_argument("--stdout-is")
    parser.add_argument("--no-stdout", action="store_true")
    parser.add_argument("--json-lines", action="store_true")
    parser.add_argument("--pty", action="store_true")
    parser.add_argument("--rewrites-lines", action="store_true")
    parser.add_argument("--no-carriage-returns", action="store_true")
    parser.add_argument("--progress-events", action="append", default=[])
    parser.add_argument("--json", choices=sorted(JSON_CHECKS))
    parser.add_argument("--write", action="append", default=[])
    parser.add_argument("--writes-nothing-in", action="append", default=[],
                        help="a folder emptied before the run that must hold no file after it")
    parser.add_argument("args", nargs=argparse.REMAINDER)
    opts = parser.parse_args()
    args = opts.args[1:] if opts.args[:1] == ["--"] else opts.args

    for item in opts.write:
        name, path = item.split(":", 1)
        with open(path, "w") as f:
            f.write(FIXTURES[name])

    for folder in opts.writes_nothing_in:
        shutil.rmtree(folder, ignore_errors=True)

    command = [opts.exe] + args
    if opts.pty:
        command = ["script", "-qec", " ".join(shlex.quote(c) for c in command), "/dev/null"]
    run = subprocess.run(command, capture_output=True, timeout=300)
    raw_stdout = run.stdout
    # Text as text mode would give it: '\r\n' and '\r' become '\n'.
    run.stdout = raw_stdout.decode().replace("\r\n", "\n").replace("\r", "\n")
    run.stderr = run.stderr.decode().replace("\r\n", "\n").replace("\r", "\n")
    print("$ semimesh " + " ".join(args))
    print("exit %d\n--- stdout\n%s--- stderr\n%s" % (run.returncode, run.stdout[:4000], run.stderr))
    expect(run.returncode == opts.exit, "exit code %d, expected %d" % (run.returncode, opts.exit))
    for text in opts.stderr_has:
        expect(text in run.stderr, "stderr lacks %r" % text)
    if opts.stderr_is is not None:
        expect(run.stderr == opts.stderr_is + "\n", "stderr is %r, expected exactly %r" % (run.stderr, opts.stderr_is))
    if opts.exit != 0:
        lines = run.stderr.splitlines()
        expect(len(lines) == 1 and lines[0].startswith("semimesh: error: "),
               "bad input must print one line starting 'semimesh: error: '")
        if args[:1] != ["run"]:  # `run` prints a progress line per stage before it stops
            expect(run.stdout == "", "nothing on stdout on error")
    for folder in opts.writes_nothing_in:
        left = [os.path.join(d, f) for d, _, files in os.walk(folder) for f in files]
        expect(not left, "the run left files in %s: %r" % (folder, left))
    for text in opts.stdout_has:
        expect(text in run.stdout, "stdout lacks %r" % text)
    if opts.rewrites_lines:
        # (text mode turns the carriage return into a newline; the erase-line sequence stays)
        expect("\x1b[K" in run.stdout, "no line is rewritten in place (erase to end of line)")
    if opts.no_carriage_returns:
        expect(b"\r" not in raw_stdout, "stdout holds a carriage return: %r" % raw_stdout[:300])
    if opts.no_stdout:
        expect(run.stdout == "", "stdout must be empty, it is %r" % run.stdout[:200])
    if opts.stdout_is is not None:
        expect(run.stdout == opts.stdout_is, "stdout is %r, expected exactly %r" % (run.stdout[:200], opts.stdout_is))
    if opts.json_lines:
        events = []
        for line in run.stdout.splitlines():
            try:
                events.append(json.loads(line))
            except ValueError as e:
                fail("stdout line is not JSON (%s): %r" % (e, line))
        expect(all(isinstance(e, dict) and "event" in e for e in events), "every line must be an object with 'event'")
        expect(events and events[-1]["event"] == "result", "the last event must be the result")
        expect(events[-1]["exit_code"] == run.returncode, "the result's exit_code must be the process's")
        started = [e["stage"] for e in events if e["event"] == "stage_started"]
        finished = [e["stage"] for e in events if e["event"] == "stage_finished"]
        expect(started and started == finished, "every stage that starts must finish: %r vs %r" % (started, finished))
        if opts.progress_events:
            check_progress_events(events, opts.progress_events)
    if opts.json:
        try:
            doc = json.loads(run.stdout)
        except ValueError as e:
            fail("stdout is not one JSON document: %s" % e)
        expect(isinstance(doc, dict), "the JSON document must be an object")
        JSON_CHECKS[opts.json](doc)
    print("cli_check: ok")


if __name__ == "__main__":
    main()
