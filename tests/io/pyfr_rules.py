"""What PyFR's Gmsh reader (pyfr/readers/gmsh.py, GmshReader; pyfr/readers/base.py,
NodalMeshAssembler) demands of an MSH file, re-implemented (Python standard library only):
  - $MeshFormat: version 4.1 or 2.2, file-type 0 (ASCII only), data-size 8;
  - $PhysicalNames: lines `dim tag "name"` (regex of _read_phys_names); tags unique across
    dimensions ("Duplicate physical entity ID"); names unique ignoring case ("Duplicate physical
    name"); names starting with "periodic" of the form periodic_<id>_l|r; at least one group of the
    highest dimension (volume);
  - $Elements: only the element types of _etype_map (lines, triangles, quads, tets, hexes,
    prisms, pyramids of orders 1..4; "Unsupported element type"); 4.1: every element block's
    entity carries a physical group (else PyFR's lookup fails); 2.2: every element has a tag;
  - pyramids have parallelogram bases (_check_pyr_parallelogram, absolute tolerance 1e-10);
  - faces paired (NodalMeshAssembler.get_connectivity, "Unpaired faces in mesh"): each volume
    element's first-order face, by its sorted vertices, is met by exactly one other volume element
    or, once, by one boundary element; a boundary element on no such face is a KeyError there.
    Here every surface element counts as a boundary one (semimesh writes surface elements only for
    its named boundary groups).

usage: pyfr_rules.py FILE.msh...   prints each violation, exit 1 if any
"""
import re
import sys

ETYPES = {1, 8, 26, 27, 2, 9, 21, 23, 3, 10, 36, 37, 4, 11, 29, 30, 5, 12, 92, 93, 6, 13, 90, 91, 7, 14, 118, 119}
PYRAMIDS = {7, 14, 118, 119}
NAME_LINE = re.compile(r'(\d+) (\d+) "((?:[^"\\]|\\.)*)"$')


def sections(path):
    with open(path, "rb") as fh:
        head = fh.read(64)
    if not head.startswith(b"$MeshFormat\n"):
        raise ValueError(f"{path}: not an MSH file")
    fmt = head.split(b"\n")[1].split()
    if fmt[1] != b"0":
        return fmt, None
    out, name, body = {}, None, []
    with open(path) as fh:
        for line in fh:
            line = line.rstrip("\n")
            if line.startswith("$End"):
                out[name] = body
                name, body = None, []
            elif line.startswith("$") and name is None:
                name = line[1:]
            else:
                body.append(line)
    return fmt, out


def check(path):
    bad = []
    fmt, sec = sections(path)
    version, ftype, dsize = (t.decode() for t in fmt)
    if version not in ("4.1", "2.2"):
        bad.append(f"mesh version {version}")
    if ftype != "0":
        bad.append("binary file: PyFR reads ASCII MSH only ('Invalid file type')")
        return bad
    if dsize != "8":
        bad.append(f"data size {dsize}")
    names = sec.get("PhysicalNames", ["0"])[1:]
    dims, seen_ids, seen_names = [], set(), set()
    for line in names:
        m = NAME_LINE.match(line)
        if not m:
            bad.append(f"malformed physical entity line {line!r}")
            continue
        dim, tag, name = int(m[1]), int(m[2]), m[3].lower()
        if tag in seen_ids:
            bad.append(f"Duplicate physical entity ID: {tag}")
        if name in seen_names:
            bad.append(f"Duplicate physical name: {name}")
        if name.startswith("periodic") and not re.match(r"periodic[ _-]([a-z0-9]+)[ _-](l|r)$", name):
            bad.append(f"invalid periodic boundary name {name}")
        seen_ids.add(tag), seen_names.add(name), dims.append(dim)
    if not dims or 3 not in dims:
        bad.append("no volume physical group ('No volume elements in mesh')")
    nodes = read_nodes(sec["Nodes"], version)
    blocks = list(read_elements(sec, version, bad))
    bad.extend(unpaired_faces(blocks))
    for etype, conn in blocks:
        if etype not in ETYPES:
            bad.append(f"Unsupported element type {etype}")
        if etype in PYRAMIDS:
            for c in conn:
                p = [nodes[c[k]] for k in (0, 1, 3, 2)]  # PyFR's base order 0 1 3 2
                if max(abs(p[0][i] - p[1][i] - p[2][i] + p[3][i]) for i in range(3)) > 1e-10:
                    bad.append("Pyramids with non-parallelogram bases are currently unsupported")
                    break
    return sorted(set(bad))


# First-order faces (Gmsh vertex order) of the volume types, by the number of vertices; the
# surface types' own vertex counts.
VOLUME_FACES = {
    4: [(0, 1, 2), (0, 1, 3), (0, 2, 3), (1, 2, 3)],
    5: [(0, 1, 2, 3), (0, 1, 4), (1, 2, 4), (2, 3, 4), (3, 0, 4)],
    6: [(0, 1, 2), (3, 4, 5), (0, 1, 4, 3), (1, 2, 5, 4), (2, 0, 3, 5)],
    8: [(0, 1, 2, 3), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)],
}
VOLUME_VERTICES = {4: 4, 11: 4, 29: 4, 30: 4, 7: 5, 14: 5, 118: 5, 119: 5,
                   6: 6, 13: 6, 90: 6, 91: 6, 5: 8, 12: 8, 92: 8, 93: 8}
SURFACE_VERTICES = {2: 3, 9: 3, 21: 3, 23: 3, 3: 4, 10: 4, 36: 4, 37: 4}


def unpaired_faces(blocks):
    """PyFR's face pairing: fluid faces pair up, the rest must each meet one boundary face."""
    resid, bad = {}, []
    for etype, conn in blocks:
        n = VOLUME_VERTICES.get(etype)
        for c in conn if n else []:
            for f in VOLUME_FACES[n]:
                key = tuple(sorted(c[k] for k in f))
                if key in resid:
                    del resid[key]
                else:
                    resid[key] = True
    for etype, conn in blocks:
        n = SURFACE_VERTICES.get(etype)
        for c in conn if n else []:
            key = tuple(sorted(c[:n]))
            if key in resid:
                del resid[key]
            else:
                bad.append("a boundary face on no unpaired volume face (KeyError in _ident_boundary_faces)")
    if resid:
        bad.append(f"Unpaired faces in mesh ({len(resid)})")
    return bad


def read_nodes(lines, version):
    nodes = {}
    if version == "2.2":
        for line in lines[1:]:
            t = line.split()
            nodes[int(t[0])] = tuple(float(x) for x in t[1:4])
        return nodes
    k = 1
    while k < len(lines):
        n = int(lines[k].split()[3])
        tags = [int(lines[k + 1 + i]) for i in range(n)]
        for i, tag in enumerate(tags):
            nodes[tag] = tuple(float(x) for x in lines[k + 1 + n + i].split())
        k += 1 + 2 * n
    return nodes


def read_elements(sec, version, bad):
    lines = sec["Elements"]
    blocks = {}
    if version == "2.2":
        for line in lines[1:]:
            t = [int(x) for x in line.split()]
            if t[2] < 1:
                bad.append(f"element {t[0]} has no physical tag")
            blocks.setdefault(t[1], []).append(t[3 + t[2]:])
        return blocks.items()
    physical = {}  # (dim, entity) -> number of physical tags
    ent = [line.split() for line in sec.get("Entities", [])]
    if ent:
        counts = [int(x) for x in ent[0]]
        row = 1
        for dim, count in enumerate(counts):
            for _ in range(count):
                t = ent[row]
                physical[(dim, int(t[0]))] = int(t[4 if dim == 0 else 7])
                row += 1
    k = 1
    while k < len(lines):
        dim, entity, etype, n = (int(x) for x in lines[k].split())
        if physical.get((dim, entity), 0) < 1:
            bad.append(f"element block on entity ({dim}, {entity}) has no physical group")
        blocks.setdefault(etype, []).extend([int(x) for x in lines[k + 1 + i].split()[1:]] for i in range(n))
        k += 1 + n
    return blocks.items()


def main(argv):
    status = 0
    for path in argv[1:]:
        bad = check(path)
        for line in bad:
            print(f"{path}: {line}")
        print(f"{path}: {'ok' if not bad else f'{len(bad)} violation(s)'}")
        status |= bool(bad)
    return status


if __name__ == "__main__":
    sys.exit(main(sys.argv))
