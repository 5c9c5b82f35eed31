"""`semimesh check` on meshes that gmsh itself writes must agree with gmsh on every element.

gmsh meshes a small box with order-3 tetrahedra (curved: the box is cut by a cylinder hole),
writes MSH 4.1 ASCII; `semimesh check` must read it and call every element valid, as gmsh's
Jacobian determinants (sampled densely) do. Then one high-order edge node is pushed far across
its elements, the file is written again, and the set of invalid elements reported by `semimesh check`
must be exactly the set where gmsh finds a negative determinant.

usage: verify_gmsh_check.py IO_WRITE_SAMPLES IO_CHECK
"""
import atexit
import json
import os
import shutil
import subprocess
import sys
import tempfile

import gmsh
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sample_map import Failures, inside_points


def gmsh_invalid_indices(tet_type):
    pts = np.vstack([inside_points("tet", n=300, seed=3),
                     [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1], [0.5, 0.5, 0], [0, 0.5, 0.5], [0.5, 0, 0.5]]])
    _, det, _ = gmsh.model.mesh.getJacobians(tet_type, pts.flatten().tolist())
    det = np.asarray(det).reshape(-1, len(pts))
    return {i for i in range(len(det)) if det[i].min() <= 0}


def run_check(checker, path):
    run = subprocess.run([checker, "check", path, "--json"], capture_output=True, text=True)
    if run.returncode not in (0, 2):
        raise SystemExit(f"semimesh check failed on {path}: {run.stderr}")
    return run.returncode, json.loads(run.stdout)


def main():
    checker = sys.argv[2]
    f = Failures()
    d = tempfile.mkdtemp(prefix="semimesh_gmsh_check_")
    atexit.register(shutil.rmtree, d, ignore_errors=True)
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.model.add("box")
    box = gmsh.model.occ.addBox(0, 0, 0, 1, 1, 1)
    hole = gmsh.model.occ.addCylinder(0.5, 0.5, 0, 0, 0, 1, 0.25)
    gmsh.model.occ.cut([(3, box)], [(3, hole)])
    gmsh.model.occ.synchronize()
    gmsh.option.setNumber("Mesh.MeshSizeMax", 0.35)
    gmsh.model.mesh.generate(3)
    gmsh.model.mesh.setOrder(3)
    gmsh.option.setNumber("Mesh.Binary", 0)
    gmsh.option.setNumber("Mesh.MshFileVersion", 4.1)
    tet3 = gmsh.model.mesh.getElementType("Tetrahedron", 3)
    path = os.path.join(d, "box_p3.msh")
    gmsh.write(path)

    ref_bad = gmsh_invalid_indices(tet3)
    code, report = run_check(checker, path)
    _, tags, _ = gmsh.model.mesh.getElements(3)
    f.check(report["elements"].get("tetrahedron", {}).get("3") == len(tags[0]), f"element count {report['elements']}")
    ours = {e["index"] for e in report["invalid"]}
    f.check(ours == ref_bad, f"gmsh's own order-3 mesh: semimesh invalid {sorted(ours)}, gmsh {sorted(ref_bad)}")
    f.check((code == 0) == (not ref_bad), f"exit code {code}")

    # Push the first node inside edge 0 of one element across that element.
    _, _, nodes = gmsh.model.mesh.getElements(3)
    conn = np.asarray(nodes[0]).reshape(len(tags[0]), -1)
    victim = len(conn) // 2
    node = int(conn[victim][4])
    x, _ = gmsh.model.mesh.getNode(node)[:2]
    opposite = np.mean([gmsh.model.mesh.getNode(int(conn[victim][k]))[0] for k in (2, 3)], axis=0)
    moved = np.asarray(x) + 1.5 * (opposite - np.asarray(x))
    gmsh.model.mesh.setNode(node, moved.tolist(), [])
    path_bad = os.path.join(d, "box_p3_folded.msh")
    gmsh.write(path_bad)
    gmsh_bad = gmsh_invalid_indices(tet3)
    code, report = run_check(checker, path_bad)
    ours = {e["index"] for e in report["invalid"]}
    f.check(victim in gmsh_bad, "the folded element is valid for gmsh: the test setup failed")
    f.check(ours == gmsh_bad, f"folded mesh: semimesh invalid {sorted(ours)}, gmsh {sorted(gmsh_bad)}")
    f.check(code == 2, f"exit code {code} for an invalid mesh")
    print(f"{len(tags[0])} order-3 tets; folded: {len(gmsh_bad)} invalid for gmsh, {len(ours)} for semimesh check")
    gmsh.finalize()
    f.finish("verify_gmsh_check")


if __name__ == "__main__":
    main()
