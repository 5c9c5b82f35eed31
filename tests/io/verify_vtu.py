"""Independent check of the VTU writer with VTK's own reader and Lagrange cells (python3-vtk9).

Each sample element (orders 1..9) is read with vtkXMLUnstructuredGridReader; VTK evaluates the
cell at random parametric points (vtkCell.EvaluateLocation) and the result must equal the known
map at the same point (VTK's parametric cube/prism [0,1] -> Gmsh's [-1,1]). A wrong node
permutation gives errors of order 0.01-1. Pyramids are linear VTK_PYRAMID cells: their 5 points
must be the images of the reference vertices. Boundary faces are checked the same way.
The compressed binary file of each sample (appended raw, vtkZLibDataCompressor) must read back
with the same points, cells, cell types and cell data as the ASCII file.

usage: verify_vtu.py IO_WRITE_SAMPLES IO_CHECK
"""
import os
import sys

import numpy as np
import vtk

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sample_map import SHAPES, Failures, curved_map, face_point, inside_points, reference_of_vertex, write_samples

# Equispaced interpolation of order 9 loses ~1e-9 to round-off; a wrong node order costs >= 1e-3.
INTERPOLATION_TOLERANCE = 1e-8

LAGRANGE = {"tet": 71, "hex": 72, "pri": 73}


def vtk_to_gmsh(name, pc):
    """VTK parametric coordinates -> Gmsh reference coordinates."""
    x = np.array(pc, dtype=float)
    if name == "hex":
        return 2 * x - 1
    if name == "pri":
        return np.array([x[0], x[1], 2 * x[2] - 1])
    return x


def gmsh_to_vtk(name, r):
    r = np.array(r, dtype=float)
    if name == "hex":
        return (r + 1) / 2
    if name == "pri":
        return np.array([r[0], r[1], (r[2] + 1) / 2])
    return r


def evaluate(cell, pcoords):
    x = [0.0, 0.0, 0.0]
    weights = [0.0] * cell.GetNumberOfPoints()
    cell.EvaluateLocation(vtk.mutable(0), list(pcoords), x, weights)
    return np.array(x)


def read_grid(path):
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    grid = vtk.vtkUnstructuredGrid()
    grid.DeepCopy(reader.GetOutput())  # the reader's output dies with the reader
    return grid


def same_grid(a, b):
    """Points, cells (type and point ids) and every cell-data array equal."""
    from vtk.util.numpy_support import vtk_to_numpy
    if a.GetNumberOfPoints() != b.GetNumberOfPoints() or a.GetNumberOfCells() != b.GetNumberOfCells():
        return False
    if a.GetNumberOfPoints() and not np.array_equal(vtk_to_numpy(a.GetPoints().GetData()),
                                                    vtk_to_numpy(b.GetPoints().GetData())):
        return False
    for c in range(a.GetNumberOfCells()):
        ca, cb = a.GetCell(c), b.GetCell(c)
        if ca.GetCellType() != cb.GetCellType() or [ca.GetPointId(k) for k in range(ca.GetNumberOfPoints())] != \
                [cb.GetPointId(k) for k in range(cb.GetNumberOfPoints())]:
            return False
    names = {a.GetCellData().GetArrayName(k) for k in range(a.GetCellData().GetNumberOfArrays())}
    if names != {b.GetCellData().GetArrayName(k) for k in range(b.GetCellData().GetNumberOfArrays())} or not names:
        return False
    return all(np.array_equal(vtk_to_numpy(a.GetCellData().GetArray(n)), vtk_to_numpy(b.GetCellData().GetArray(n)))
               for n in names)


def main():
    writer = sys.argv[1]
    d = write_samples(writer)
    f = Failures()
    for name in SHAPES:
        for p in range(1, 10):
            path = os.path.join(d, f"{name}_{p}.vtu")
            grid = read_grid(path)
            f.check(same_grid(grid, read_grid(os.path.join(d, f"{name}_{p}_z.vtu"))),
                    f"{path}: the compressed binary file differs from the ASCII file")
            f.check(grid.GetNumberOfCells() == 1 + {"tet": 4, "pyr": 5, "pri": 5, "hex": 6}[name], f"{path}: cell count")
            cell = grid.GetCell(0)
            if name == "pyr":
                f.check(cell.GetCellType() == 14, f"{path}: pyramid cell type {cell.GetCellType()}")
                pts = np.array([cell.GetPoints().GetPoint(k) for k in range(5)])
                err = np.abs(pts - curved_map(SHAPES["pyr"][1], p)).max()
                f.check(err < 1e-12, f"{path}: pyramid vertices off by {err:.3g}")
            else:
                f.check(cell.GetCellType() == LAGRANGE[name], f"{path}: cell type {cell.GetCellType()}")
                uvw = inside_points(name)
                got = np.array([evaluate(cell, gmsh_to_vtk(name, r)) for r in uvw])
                err = np.abs(got - curved_map(uvw, p)).max()
                f.check(err < INTERPOLATION_TOLERANCE, f"{path}: VTK evaluation differs from the map by {err:.3g}")
            for c in range(1, grid.GetNumberOfCells()):
                face = grid.GetCell(c)
                quad = face.GetCellType() == 70
                f.check(face.GetCellType() in (69, 70), f"{path}: boundary cell type {face.GetCellType()}")
                nv = 4 if quad else 3
                refv = [reference_of_vertex(name, p, np.array(face.GetPoints().GetPoint(k))) for k in range(nv)]
                for uv in ([(-0.3, 0.2), (0.5, -0.6)] if quad else [(0.2, 0.3), (0.6, 0.1)]):
                    pc = [(uv[0] + 1) / 2, (uv[1] + 1) / 2, 0] if quad else [uv[0], uv[1], 0]
                    err = np.abs(evaluate(face, pc) - curved_map([face_point(refv, uv, quad)], p)[0]).max()
                    f.check(err < INTERPOLATION_TOLERANCE, f"{path}: boundary cell {c} off the map by {err:.3g}")
    f.finish("verify_vtu")


if __name__ == "__main__":
    main()
