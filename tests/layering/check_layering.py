#!/usr/bin/env python3
"""Checks that no part of semimesh includes a header of a part above it.

The parts are the top-level folders added by the top-level CMakeLists.txt, in the order of their
add_subdirectory() lines: that order is the dependency order (cadapi first, apps last). A header
belongs to the part whose folder holds it (under an include/ folder). Every #include of every
source and header in a part must name a header of the same part or of one before it.

usage: check_layering.py ROOT             checks the tree at ROOT (exit 1 and the offending lines)
       check_layering.py --self-test      builds a small tree with a wrong include: it must fail
"""
import pathlib
import re
import sys
import tempfile

INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]([^>"]+)[>"]')
SUBDIR = re.compile(r'^\s*add_subdirectory\(\s*([A-Za-z0-9_]+)\s*\)')
SOURCES = {".cpp", ".hpp", ".h", ".cc"}


def parts_in_order(root):
    parts = []
    for line in (root / "CMakeLists.txt").read_text().splitlines():
        m = SUBDIR.match(line)
        if m and m.group(1) not in ("tests", "bench"):
            parts.append(m.group(1))
    return parts


def owner_of_headers(root, parts):
    owner = {}
    for index, part in enumerate(parts):
        for header in (root / part).rglob("*"):
            if header.suffix not in SOURCES or "include" not in header.relative_to(root / part).parts:
                continue
            rel = header.relative_to(root / part).parts
            name = "/".join(rel[rel.index("include") + 1:])
            owner[name] = index
    return owner


def violations(root):
    parts = parts_in_order(root)
    if not parts:
        return [f"{root}/CMakeLists.txt: no add_subdirectory() parts found"]
    owner = owner_of_headers(root, parts)
    found = []
    for index, part in enumerate(parts):
        for source in sorted((root / part).rglob("*")):
            if source.suffix not in SOURCES:
                continue
            for number, line in enumerate(source.read_text(errors="replace").splitlines(), 1):
                m = INCLUDE.match(line)
                if not m or m.group(1) not in owner:
                    continue
                above = owner[m.group(1)]
                if above > index:
                    found.append(f"{source.relative_to(root)}:{number}: part '{part}' includes "
                                 f"{m.group(1)} of part '{parts[above]}', which comes after it "
                                 f"(order: {' < '.join(parts)})")
    return found


def self_test():
    with tempfile.TemporaryDirectory() as tmp:
        root = pathlib.Path(tmp)
        (root / "CMakeLists.txt").write_text("add_subdirectory(low)\nadd_subdirectory(high)\nadd_subdirectory(tests)\n")
        (root / "low/include/x/low").mkdir(parents=True)
        (root / "high/include/x/high").mkdir(parents=True)
        (root / "high/include/x/high/b.hpp").write_text('#include "x/low/a.hpp"\n')
        (root / "low/include/x/low/a.hpp").write_text("#include <vector>\n")
        if violations(root):
            print("self-test: a correct tree was rejected:", violations(root))
            return 1
        (root / "low/src").mkdir()
        (root / "low/src/a.cpp").write_text('#include "x/low/a.hpp"\n#include "x/high/b.hpp"\n')
        found = violations(root)
        if len(found) != 1 or "low/src/a.cpp:2" not in found[0]:
            print("self-test: the wrong include was not reported as expected:", found)
            return 1
        print("self-test: the wrong include is reported:", found[0])
        return 0


def main():
    if sys.argv[1:] == ["--self-test"]:
        return self_test()
    if len(sys.argv) != 2:
        print(__doc__)
        return 2
    root = pathlib.Path(sys.argv[1])
    found = violations(root)
    for line in found:
        print(line)
    print(f"layering: {len(found)} include(s) of a later part in {' < '.join(parts_in_order(root))}")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
