"""Shared by the verify_*.py scripts: the map that io_write_samples applies to the reference
element (must match curved_map() in write_samples.cpp), Gmsh's reference vertices, and a helper
that runs io_write_samples into a temporary directory."""
import atexit
import shutil
import subprocess
import tempfile

import numpy as np

SHAPES = {  # name -> (gmsh family, reference vertices in Gmsh order (gmsh.info "Node ordering"))
    "tet": ("Tetrahedron", [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]),
    "pyr": ("Pyramid", [(-1, -1, 0), (1, -1, 0), (1, 1, 0), (-1, 1, 0), (0, 0, 1)]),
    "pri": ("Prism", [(0, 0, -1), (1, 0, -1), (0, 1, -1), (0, 0, 1), (1, 0, 1), (0, 1, 1)]),
    "hex": ("Hexahedron", [(-1, -1, -1), (1, -1, -1), (1, 1, -1), (-1, 1, -1),
                           (-1, -1, 1), (1, -1, 1), (1, 1, 1), (-1, 1, 1)]),
}


def curved_map(r, p):
    """r: (n, 3) reference points -> (n, 3) physical points; polynomial of degree p."""
    r = np.atleast_2d(np.asarray(r, dtype=float))
    a, b, c = r[:, 0], r[:, 1], r[:, 2]
    s1 = 0.3 * a + 0.5 * b - 0.2 * c + 0.1
    s2 = -0.4 * a + 0.2 * b + 0.6 * c - 0.3
    s3 = 0.5 * a - 0.3 * b + 0.4 * c + 0.2
    k = 0.1 / p  # keeps det J > 0 on every reference element up to order 9 (0.1 folds the order-8 hex)
    return np.stack([a + k * s1**p + 0.05 * s2, b + k * s2**p + 0.05 * s3, c + k * s3**p + 0.05 * s1], axis=1)


def inside_points(name, n=40, seed=1):
    """Random points strictly inside the Gmsh reference element."""
    rng = np.random.default_rng(seed)
    out = []
    while len(out) < n:
        x = rng.uniform(-1, 1, 3)
        if name == "tet":
            x = rng.uniform(0, 1, 3)
            ok = x.sum() < 1
        elif name == "pri":
            x[:2] = rng.uniform(0, 1, 2)
            ok = x[0] + x[1] < 1
        elif name == "pyr":
            x[2] = rng.uniform(0, 0.95)
            ok = abs(x[0]) < 1 - x[2] and abs(x[1]) < 1 - x[2]
        else:
            ok = True
        if ok:
            out.append(x)
    return np.array(out)


def face_point(ref_vertices, uv, quad):
    """Reference point of a face at its own parametric point (Gmsh tri (0,0)(1,0)(0,1) or quad [-1,1]^2)."""
    v = np.asarray(ref_vertices, dtype=float)
    u, w = uv
    if quad:
        s, t = (u + 1) / 2, (w + 1) / 2
        return (1 - s) * (1 - t) * v[0] + s * (1 - t) * v[1] + s * t * v[2] + (1 - s) * t * v[3]
    return (1 - u - w) * v[0] + u * v[1] + w * v[2]


def reference_of_vertex(name, p, x):
    """Reference vertex whose image under curved_map is x (vertices are distinct images)."""
    ref = np.array(SHAPES[name][1], dtype=float)
    d = np.linalg.norm(curved_map(ref, p) - x, axis=1)
    k = int(np.argmin(d))
    assert d[k] < 1e-9, f"{name} P{p}: vertex {x} is not the image of a reference vertex"
    return ref[k]


def write_samples(writer):
    d = tempfile.mkdtemp(prefix="semimesh_io_")
    atexit.register(shutil.rmtree, d, ignore_errors=True)
    subprocess.run([writer, d], check=True)
    return d


class Failures:
    def __init__(self):
        self.messages = []

    def check(self, ok, message):
        if not ok:
            self.messages.append(message)

    def finish(self, what):
        for m in self.messages[:50]:
            print("FAIL:", m)
        if self.messages:
            print(f"{what}: {len(self.messages)} failures")
            raise SystemExit(1)
        print(f"{what}: all checks passed")
