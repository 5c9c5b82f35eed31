"""Nektar++ load rules (nektar_rules.py) on what the writer produces, with negative controls.

usage: verify_nektar_rules.py samples IO_WRITE_SAMPLES
         every sample element (4 shapes, orders 1..9) and the multi-element fixtures (two tets
         sharing a face in both creation orders, a prism stack under a tet, a pyramid beside a tet,
         a hex-prism interface; orders 1, 2, 4), plain and compressed: each passes and both
         encodings decode to the same mesh; mutated copies of them (a rotated triangle, swapped prism
         faces, a triangle with PolyEvenlySpaced points, reversed edge points, a mirrored tet) fail.
       verify_nektar_rules.py controls DIR
         the six meshes shipped with Nektar++ (DIR = ../shared/testdata/nektar) pass (positive
         controls: NekMesh loads them all) and mutated copies fail; exit 77 (skipped) without DIR.
"""
import copy
import os
import sys
import tempfile
import xml.etree.ElementTree as ET

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import nektar_rules
from sample_map import SHAPES, Failures, write_samples

CONTROLS = ["Helmholtz3D_Prism.xml", "Helmholtz3D_Pyr.xml", "Helmholtz3D_Tet.xml", "extract_curved_face.xml",
            "jac_list_tet_face.xml", "tube.xml"]


def violations(path):
    return nektar_rules.check(nektar_rules.read(path))


def geometry(tree):
    return tree.getroot().find("GEOMETRY")


def rotate_triangle(tree):
    """The first triangle's edge list rotated by one (its vertices rotate: a wrong third vertex)."""
    t = next(f for f in geometry(tree).find("FACE") if f.tag == "T")
    e = t.text.split()
    t.text = " ".join(e[1:] + e[:1])


def swap_prism_faces(tree):
    """Faces 1 and 3 (the two triangles) of the first prism swapped."""
    r = geometry(tree).find("ELEMENT").find("R")
    f = r.text.split()
    f[1], f[3] = f[3], f[1]
    r.text = " ".join(f)


def poly_triangle(tree):
    """A curved triangle's nodal points declared PolyEvenlySpaced."""
    c = next(c for c in geometry(tree).find("CURVED") if c.tag == "F" and c.get("TYPE", "").startswith("NodalTri"))
    c.set("TYPE", "PolyEvenlySpaced")


def reverse_edge_points(tree):
    """A curved edge's points listed from its second vertex to its first."""
    c = next(c for c in geometry(tree).find("CURVED") if c.tag == "E")
    nums = c.text.split()
    pts = [nums[k:k + 3] for k in range(0, len(nums), 3)]
    c.text = " ".join(x for p in reversed(pts) for x in p)


def mirror(tree):
    """Every vertex mirrored in x: the same faces now number each element left-handed."""
    for v in geometry(tree).find("VERTEX"):
        x = v.text.split()
        v.text = " ".join([str(-float(x[0]))] + x[1:])
    curved = geometry(tree).find("CURVED")
    for c in (curved if curved is not None else []):
        nums = c.text.split()
        c.text = " ".join(str(-float(t)) if k % 3 == 0 else t for k, t in enumerate(nums))


def mutant_fails(f, path, mutate, what, workdir):
    tree = ET.parse(path)
    mutate(tree)
    out = os.path.join(workdir, f"mutant_{what}_{os.path.basename(path)}")
    tree.write(out)
    f.check(len(violations(out)) > 0, f"{path}: mutated ({what}) but the rules checker accepts it")


def samples(writer):
    d = write_samples(writer)
    f = Failures()
    files = [f"{name}_{p}" for name in SHAPES for p in range(1, 10)]
    files += [f"fix_{name}_{p}" for name in ("tets_ab", "tets_ba", "stack", "pyr_tet", "hex_prism") for p in (1, 2, 4)]
    for base in files:
        plain, packed = os.path.join(d, base + ".xml"), os.path.join(d, base + "_z.xml")
        for path in (plain, packed):
            bad = violations(path)
            f.check(not bad, f"{path}: {bad[:3]}")
        f.check(nektar_rules.read(plain).same_as(nektar_rules.read(packed)), f"{packed}: differs from {plain}")
    with tempfile.TemporaryDirectory() as work:
        for name in ("tet", "pyr", "pri", "fix_stack", "fix_pyr_tet", "fix_tets_ba"):
            mutant_fails(f, os.path.join(d, f"{name}_2.xml"), rotate_triangle, "rotated_T", work)
        for p in (1, 3):
            mutant_fails(f, os.path.join(d, f"pri_{p}.xml"), swap_prism_faces, "swapped_prism_faces", work)
            mutant_fails(f, os.path.join(d, f"fix_stack_{min(p, 2)}.xml"), swap_prism_faces, "swapped_faces", work)
        for name in SHAPES:
            mutant_fails(f, os.path.join(d, f"{name}_3.xml"), reverse_edge_points, "reversed_edge", work)
        for name in ("tet", "pri", "pyr"):
            mutant_fails(f, os.path.join(d, f"{name}_4.xml"), poly_triangle, "poly_triangle", work)
        for name in SHAPES:
            mutant_fails(f, os.path.join(d, f"{name}_1.xml"), mirror, "mirrored", work)
    f.finish("verify_nektar_rules samples")


def controls(folder):
    if not os.path.isdir(folder):
        print(f"SKIPPED: no Nektar++ reference meshes in {folder} (positive controls need them)")
        return 77
    f = Failures()
    for name in CONTROLS:
        path = os.path.join(folder, name)
        bad = violations(path)
        f.check(not bad, f"{path}: a mesh NekMesh loads breaks the re-implemented rules: {bad[:3]}")
    with tempfile.TemporaryDirectory() as work:
        for name in ("tube.xml", "Helmholtz3D_Tet.xml", "Helmholtz3D_Prism.xml", "Helmholtz3D_Pyr.xml"):
            mutant_fails(f, os.path.join(folder, name), rotate_triangle, "rotated_T", work)
        for name in ("tube.xml", "Helmholtz3D_Prism.xml"):
            mutant_fails(f, os.path.join(folder, name), swap_prism_faces, "swapped_prism_faces", work)
        mutant_fails(f, os.path.join(folder, "extract_curved_face.xml"), poly_triangle, "poly_triangle", work)
        for name in ("Helmholtz3D_Tet.xml", "tube.xml"):
            mutant_fails(f, os.path.join(folder, name), mirror, "mirrored", work)
    f.finish("verify_nektar_rules controls")
    return 0


if __name__ == "__main__":
    if len(sys.argv) != 3 or sys.argv[1] not in ("samples", "controls"):
        print(__doc__)
        sys.exit(1)
    sys.exit(samples(sys.argv[2]) if sys.argv[1] == "samples" else controls(sys.argv[2]))
