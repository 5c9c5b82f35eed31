#!/usr/bin/python3
"""Gmsh's own boundary-layer wing at order 3 with fast curving: the peer figure of issue 25
("per-element time <= 0.2 of Gmsh's on its boundary-layer wing", Debian's gmsh 4.8).

Builds with Gmsh's API (built-in geo kernel) a case like our paper's (examples/naca0012_wing.toml):
a NACA 0012 wing of chord 1 and span 3 with its squared-off trailing edge (a4 = -0.1015) standing on
the wall z = 0, a flat tip, the box [-10, 11] x [-10, 10] x [0, 10] around it; a boundary layer of
5 layers growing by 2, 0.1 chord thick in all, extruded along the wing's mesh normals
(geo.extrudeBoundaryLayer); tetrahedra in the rest (Gmsh's default 3D Delaunay). Then order 3 and
Gmsh's fast curving. Times, separately and in total: generate(3) (order 1), setOrder(3) and
optimize("HighOrderFastCurving"), the optimiser Mesh.HighOrderOptimize = 4 selects ("Optimize
high-order meshes? (0: none, 1: optimization, 2: elastic+optimization, 3: elastic, 4: fast
curving)", Gmsh 4.8's own option help) and that setOrder does not run by itself; --one-call times
the same as one generate(3) with Mesh.ElementOrder = 3 instead (measured: the same element and
invalid counts, the same time).

The layer is made of tetrahedra (3 per prism: the unrecombined extrusion) by default: Gmsh 4.8
cannot curve order-3 prisms ("FaceClosureFull not implemented for prisms of order 3"); with
--prisms, fast curving runs but the prisms keep setOrder's invalid count and worst bound.

The total times Gmsh's meshing only; when the mesh is written (for the check, or --write) the write
is timed too and printed with "total with write": our runs' time includes writing their file.

Validity, after the timing: the mesh is written to a temporary binary MSH file and certified with
tests/pipeline/gmsh_validity.py: Gmsh's own Plugin(AnalyseMeshQuality) Jacobian bounds for
tetrahedra; order-3 prisms (the plugin cannot build them either) as the three order-3 hexahedra
that tile each exactly. An element whose certified min J / max J is <= 0 is invalid.

The wing's sides are meshed structured along the span (geo extrusion with layers): their
triangles' normals are then exactly horizontal, so the layer's root stays in the wall's plane and
the wall is a plane surface with the layer's footprint as its hole (with unstructured sides the
averaged normals at the root tilt: the footprint left z = 0 by 0.004 in a trial).

usage: gmsh_bl_wing.py [--threads N] [--scale S] [--chord-points N] [--span-layers N] [--bump B]
                       [--far-size H] [--layers N] [--ratio R] [--thickness T] [--prisms]
                       [--no-curving] [--one-call] [--no-check] [--write FILE] [--verbose]
  --threads N: General.NumThreads and Mesh.MaxNumThreads3D (default: Gmsh's own, 1 and 0)
  --scale S: multiplies the wing's point counts (chordwise and spanwise): elements grow ~S^2;
             the defaults give 152,335 order-3 tetrahedra
"""
import argparse
import math
import os
import resource
import sys
import tempfile
import time

import gmsh

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "tests", "pipeline"))

CHORD, SPAN, THICKNESS = 1.0, 3.0, 0.12
BOX = (-10.0, -10.0, 0.0, 11.0, 10.0, 10.0)  # the paper case's far-field box


def half_thickness(x):
    """NACA 4-digit half thickness, a4 = -0.1015: the classic squared-off trailing edge."""
    return 5 * THICKNESS * CHORD * (0.2969 * math.sqrt(x) - 0.1260 * x - 0.3516 * x ** 2 + 0.2843 * x ** 3
                                    - 0.1015 * x ** 4)


def cpu_seconds():
    usage = resource.getrusage(resource.RUSAGE_SELF)  # every thread of this process
    return usage.ru_utime + usage.ru_stime


def build(args):
    """The wing, its boundary layer and the box in the geo kernel, synchronised."""
    g = gmsh.model.geo
    # Section points, cosine spaced (dense at both ends); the splines pass through them.
    n = 80
    xs = [0.5 * (1 - math.cos(math.pi * i / n)) for i in range(1, n + 1)]
    le = g.addPoint(0, 0, 0)
    upper = [g.addPoint(x * CHORD, half_thickness(x), 0) for x in xs]
    lower = [g.addPoint(x * CHORD, -half_thickness(x), 0) for x in xs]
    # One loop LE -> lower -> base -> upper -> LE: counter-clockwise seen from +z, so every side
    # extruded along +z (and the tip's plane face) has its normal out of the wing, the side the
    # boundary layer grows on.
    section = [g.addSpline([le] + lower), g.addLine(lower[-1], upper[-1]), g.addSpline(upper[::-1] + [le])]
    chordwise = max(2, round(args.chord_points * args.scale))
    g.mesh.setTransfiniteCurve(section[0], chordwise, "Bump", args.bump)  # dense at LE and TE
    g.mesh.setTransfiniteCurve(section[1], args.te_points)
    g.mesh.setTransfiniteCurve(section[2], chordwise, "Bump", args.bump)
    spanwise = max(1, round(args.span_layers * args.scale))
    sides, tip_curves = [], []
    for curve in section:
        out = g.extrude([(1, curve)], 0, 0, SPAN, [spanwise])  # structured along the span
        tip_curves.append(out[0][1])
        sides.append(out[1][1])
    tip = g.addPlaneSurface([g.addCurveLoop(tip_curves)])
    wing = sides + [tip]

    # Layer k's outer face at h1 (r^k - 1) / (r - 1), the last one at the thickness.
    r, layers = args.ratio, args.layers
    first = args.thickness * (r - 1) / (r ** layers - 1) if r != 1 else args.thickness / layers
    heights = [first * (r ** (k + 1) - 1) / (r - 1) if r != 1 else first * (k + 1) for k in range(layers)]
    layer = g.extrudeBoundaryLayer([(2, s) for s in wing], [1] * layers, heights, args.prisms)
    # Per wing face: its outer face, its volume, then one lateral face per edge; a lateral face
    # listed once is on no other face's edge: the root's, in the wall's plane.
    outer = [layer[i - 1][1] for i, (dim, _) in enumerate(layer) if dim == 3]
    seen = {}
    for dim, tag in layer:
        if dim == 2 and tag not in outer:
            seen[tag] = seen.get(tag, 0) + 1
    root_faces = [tag for tag, count in seen.items() if count == 1]
    g.synchronize()
    edges = {}
    for _, curve in gmsh.model.getBoundary([(2, f) for f in root_faces], combined=False, oriented=False):
        edges[abs(curve)] = edges.get(abs(curve), 0) + 1
    footprint = [c for c, k in edges.items() if k == 1 and c not in section]  # the layer's outer rim

    x0, y0, z0, x1, y1, z1 = BOX
    corner = {}
    for i, x in enumerate((x0, x1)):
        for j, y in enumerate((y0, y1)):
            for k, z in enumerate((z0, z1)):
                corner[i, j, k] = g.addPoint(x, y, z, args.far_size)
    lines = {}

    def line(a, b):
        if (b, a) in lines:  # each box edge once, shared by its two faces
            return -lines[b, a]
        if (a, b) not in lines:
            lines[a, b] = g.addLine(corner[a], corner[b])
        return lines[a, b]

    def loop(*points):
        return g.addCurveLoop([line(points[i], points[(i + 1) % 4]) for i in range(4)])

    wall = g.addPlaneSurface([loop((0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)),
                              g.addCurveLoop(footprint, reorient=True)])  # the root faces fill its hole
    box = [g.addPlaneSurface([loop(*f)]) for f in (
        ((0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)), ((0, 0, 0), (1, 0, 0), (1, 0, 1), (0, 0, 1)),
        ((0, 1, 0), (1, 1, 0), (1, 1, 1), (0, 1, 1)), ((0, 0, 0), (0, 1, 0), (0, 1, 1), (0, 0, 1)),
        ((1, 0, 0), (1, 1, 0), (1, 1, 1), (1, 0, 1)))]
    g.addVolume([g.addSurfaceLoop([wall] + box + outer)])
    g.synchronize()


def element_counts(dim):
    """{name: count} of the mesh's elements of dimension dim (names without calling
    getElementProperties, which Gmsh 4.8 refuses for prisms of order >= 3)."""
    names = {}
    for family in ("Tetrahedron", "Prism", "Pyramid", "Hexahedron", "Triangle", "Quadrangle"):
        for order in range(1, 4):
            names[gmsh.model.mesh.getElementType(family, order)] = family.lower()
    types, tags, _ = gmsh.model.mesh.getElements(dim)
    counts = {}
    for t, tg in zip(types, tags):
        counts[names.get(t, str(t))] = counts.get(names.get(t, str(t)), 0) + len(tg)
    return counts


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--threads", type=int, default=None)
    parser.add_argument("--scale", type=float, default=1.0)
    parser.add_argument("--chord-points", type=int, default=52, help="points along each side's chord")
    parser.add_argument("--bump", type=float, default=0.25, help="Gmsh's Bump coefficient: < 1 clusters at LE and TE")
    parser.add_argument("--te-points", type=int, default=3, help="points across the trailing-edge base")
    parser.add_argument("--span-layers", type=int, default=38, help="cells along the span")
    parser.add_argument("--far-size", type=float, default=2.0, help="mesh size at the box's corners")
    parser.add_argument("--layers", type=int, default=5)
    parser.add_argument("--ratio", type=float, default=2.0)
    parser.add_argument("--thickness", type=float, default=0.1, help="the boundary layer's total thickness")
    parser.add_argument("--prisms", action="store_true", help="recombine the layer into prisms")
    parser.add_argument("--no-curving", action="store_true", help="setOrder only")
    parser.add_argument("--one-call", action="store_true",
                        help="Mesh.ElementOrder = order: generate(3) elevates and curves itself, timed as one")
    parser.add_argument("--order", type=int, default=3)
    parser.add_argument("--no-check", action="store_true", help="skip the validity certification")
    parser.add_argument("--write", help="also keep the mesh in this MSH file")
    parser.add_argument("--verbose", action="store_true", help="Gmsh's own log on the terminal")
    args = parser.parse_args()

    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 1 if args.verbose else 0)
    if args.threads is not None:
        gmsh.option.setNumber("General.NumThreads", args.threads)
        gmsh.option.setNumber("Mesh.MaxNumThreads3D", args.threads)
    threads = gmsh.option.getNumber("General.NumThreads"), gmsh.option.getNumber("Mesh.MaxNumThreads3D")
    gmsh.option.setNumber("Mesh.HighOrderOptimize", 4)  # fast curving (run by generate() with --one-call)
    # Gmsh 4.8's fast curving logs "FaceClosureFull not implemented for prisms of order 3" once even
    # on a layer of tetrahedra; its default (2) turns that into an exception midway through the
    # curving, 0 lets it finish.
    gmsh.option.setNumber("General.AbortOnError", 0)
    gmsh.model.add("gmsh_bl_wing")
    build(args)

    stages, linear = [], None
    steps = [("generate(3)", lambda: gmsh.model.mesh.generate(3)),
             ("setOrder(%d)" % args.order, lambda: gmsh.model.mesh.setOrder(args.order)),
             ("fast curving", lambda: gmsh.model.mesh.optimize("HighOrderFastCurving"))]
    if args.one_call:
        gmsh.option.setNumber("Mesh.ElementOrder", args.order)
        gmsh.option.setNumber("Mesh.HighOrderOptimize", 0 if args.no_curving else 4)
        steps = [("generate(3) all", steps[0][1])]
    for name, run in steps[:2 if args.no_curving else 3]:
        wall, cpu = time.monotonic(), cpu_seconds()
        run()
        stages.append((name, time.monotonic() - wall, cpu_seconds() - cpu))
        if name == "generate(3)":
            linear = element_counts(3)
    peak_mb = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024

    volume, surface = element_counts(3), element_counts(2)
    elements = sum(volume.values())
    print("Gmsh %s, General.NumThreads %g, Mesh.MaxNumThreads3D %g" % (gmsh.__version__, *threads))
    print("volume elements (order %d): %d = %s" % (args.order, elements,
                                                     ", ".join("%d %ss" % (n, k) for k, n in sorted(volume.items()))))
    print("surface elements: %s" % ", ".join("%d %ss" % (n, k) for k, n in sorted(surface.items())))
    if linear and linear != volume:
        print("(order 1 had %s)" % linear)
    total_wall, total_cpu = sum(s[1] for s in stages), sum(s[2] for s in stages)
    print("%-14s %9s %9s %12s %12s" % ("stage", "wall s", "CPU s", "wall us/el", "CPU us/el"))
    for name, wall, cpu in stages + [("total", total_wall, total_cpu)]:
        print("%-14s %9.2f %9.2f %12.1f %12.1f" % (name, wall, cpu, 1e6 * wall / elements, 1e6 * cpu / elements))
    print("peak RSS %.0f MB, load average %.2f" % (peak_mb, os.getloadavg()[0]))

    if args.no_check and not args.write:
        gmsh.finalize()
        return
    gmsh.option.setNumber("Mesh.Binary", 1)
    path = args.write or os.path.join(tempfile.mkdtemp(prefix="gmsh_bl_wing."), "wing.msh")
    wall = time.monotonic()
    gmsh.write(path)
    write_wall = time.monotonic() - wall
    # Our runs' time includes writing the mesh file; Gmsh's total above does not: its own write of
    # the same mesh (binary MSH 4.1), for a comparison of mesh files made.
    print("write (binary MSH %.0f MB): %.2f s wall; total with write %.2f s"
          % (os.path.getsize(path) / 1e6, write_wall, total_wall + write_wall))
    gmsh.finalize()
    if not args.no_check:
        from gmsh_validity import certified_ratios  # opens its own Gmsh sessions
        ratios = certified_ratios(path)
        kinds = (("tets etc. (Gmsh's plugin)", ratios["direct"]), ("prisms (as 3 hexes each)", ratios["prisms"]),
                 ("pyramids (exact bounds)", ratios["pyramids"]))
        invalid = sum(sum(1 for v in values if v <= 0) for _, values in kinds)
        print("invalid elements (certified min J / max J <= 0): %d of %d" % (invalid, elements))
        for label, values in kinds:
            if values:
                print("  %-26s %d elements, %d invalid, smallest min J / max J %.4g"
                      % (label, len(values), sum(1 for v in values if v <= 0), min(values)))
    if not args.write:
        os.remove(path)
        os.rmdir(os.path.dirname(path))


if __name__ == "__main__":
    main()
