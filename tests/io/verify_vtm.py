"""The ParaView multiblock (`vtm` format) that `semimesh run` writes, read by VTK's own reader.

Runs the CLI on the coarse wing (order 2, two layers) with the formats msh41, vtu and vtm, then:
  - vtkXMLMultiBlockDataReader reads NAME.vtm: block 0 is named "volume", then one block per
    boundary group, named after it, in the MSH file's order of the 2D physical groups;
  - cell counts, from gmsh reading the MSH file (an independent reader of another writer): the
    volume block holds as many cells as the mesh has 3D elements, each group's block as many as
    the group has faces;
  - geometry, against the single VTU file (volume cells first, then faces with "boundary_group"):
    the volume block has the VTU's points and its first cells' connectivity and types; each group
    block's cells have the same types and point coordinates as the VTU's cells of that group, in
    order, and only the points they use;
  - atomic: a run whose piece folder cannot be put in place (a file stands at its path) fails,
    leaves that file as it was and no NAME.vtm, no temporary folder.

usage: verify_vtm.py --exe SEMIMESH --config CONFIG --workdir DIR
"""
import argparse
import os
import shutil
import subprocess
import sys

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sample_map import Failures


def run(exe, config, workdir, formats):
    cmd = [exe, "run", config, "-o", workdir, "--set", "highorder.order=2", "--set", "boundary_layer.layers=2",
           "--set", "output.formats=[" + ",".join(f'"{f}"' for f in formats) + "]"]
    return subprocess.run(cmd, capture_output=True, text=True)


def grid_arrays(grid):
    """points, per-cell point lists, cell types, cell data of a vtkUnstructuredGrid."""
    points = vtk_to_numpy(grid.GetPoints().GetData()).copy() if grid.GetNumberOfPoints() else np.zeros((0, 3))
    offsets = vtk_to_numpy(grid.GetCells().GetOffsetsArray())
    connectivity = vtk_to_numpy(grid.GetCells().GetConnectivityArray())
    cells = [connectivity[offsets[i]:offsets[i + 1]] for i in range(len(offsets) - 1)]
    types = vtk_to_numpy(grid.GetCellTypesArray()).copy()
    data = {grid.GetCellData().GetArrayName(k): vtk_to_numpy(grid.GetCellData().GetArray(k)).copy()
            for k in range(grid.GetCellData().GetNumberOfArrays())}
    return points, cells, types, data


def read_vtu(path):
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    return grid_arrays(reader.GetOutput())


def read_vtm(path):
    """[(name, arrays)] per block, in order."""
    reader = vtk.vtkXMLMultiBlockDataReader()
    reader.SetFileName(path)
    reader.Update()
    blocks = reader.GetOutput()
    out = []
    for b in range(blocks.GetNumberOfBlocks()):
        name = blocks.GetMetaData(b).Get(vtk.vtkCompositeDataSet.NAME())
        out.append((name, grid_arrays(blocks.GetBlock(b))))
    return out


def gmsh_counts(path):
    """3D element count and {2D physical group name: face count} as gmsh reads the MSH file."""
    import gmsh
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.open(path)
    volume = sum(len(tags) for tags in gmsh.model.mesh.getElements(3)[1])
    faces = {}
    for dim, tag in gmsh.model.getPhysicalGroups(2):
        name = gmsh.model.getPhysicalName(dim, tag)
        faces[name] = sum(len(t) for e in gmsh.model.getEntitiesForPhysicalGroup(dim, tag)
                          for t in gmsh.model.mesh.getElements(dim, e)[1])
    gmsh.finalize()
    return volume, faces


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    ap.add_argument("--config", required=True)
    ap.add_argument("--workdir", required=True)
    a = ap.parse_args()
    shutil.rmtree(a.workdir, ignore_errors=True)
    done = run(a.exe, a.config, a.workdir, ["msh41", "vtu", "vtm"])
    if done.returncode != 0:
        print(done.stdout[-3000:], done.stderr[-3000:])
        sys.exit(f"semimesh run failed with code {done.returncode}")
    path = lambda name: os.path.join(a.workdir, name)
    f = Failures()

    volume_count, face_counts = gmsh_counts(path("coarse.msh"))
    blocks = read_vtm(path("coarse.vtm"))
    names = [name for name, _ in blocks]
    print("blocks:", ", ".join(f"{n} ({len(arrays[1])} cells)" for n, arrays in blocks))
    f.check(names == ["volume"] + list(face_counts), f"block names {names}, expected volume then {list(face_counts)}")
    f.check(sorted(os.listdir(path("coarse"))) == sorted(["volume.vtu"] + [f"boundary{g}_{n}.vtu" for g, n in
                                                                           enumerate(face_counts)]),
            f"piece folder holds {sorted(os.listdir(path('coarse')))}")
    counts = {name: len(arrays[1]) for name, arrays in blocks}
    f.check(counts.get("volume") == volume_count, f"volume block {counts.get('volume')} cells, gmsh reads "
                                                  f"{volume_count} 3D elements")
    for group, n in face_counts.items():
        f.check(counts.get(group) == n, f"block '{group}' has {counts.get(group)} cells, gmsh reads {n} faces")

    points, cells, types, data = read_vtu(path("coarse.vtu"))
    volume_points, volume_cells, volume_types, _ = blocks[0][1]
    f.check(np.array_equal(volume_points, points), "the volume block's points differ from the VTU's")
    f.check(len(volume_cells) == volume_count and
            all(np.array_equal(volume_cells[i], cells[i]) for i in range(len(volume_cells))) and
            np.array_equal(volume_types, types[:len(volume_cells)]), "the volume block's cells differ from the VTU's")
    group_of = data["boundary_group"]
    for g, (name, (bpoints, bcells, btypes, bdata)) in enumerate(blocks[1:]):
        mine = [i for i in range(len(cells)) if group_of[i] == g]
        f.check(len(mine) == len(bcells), f"block '{name}': {len(bcells)} cells, the VTU has {len(mine)} in group {g}")
        f.check(np.array_equal(btypes, types[mine]), f"block '{name}': cell types differ from the VTU's")
        same = len(mine) == len(bcells) and all(np.array_equal(bpoints[bcells[k]], points[cells[i]])
                                                 for k, i in enumerate(mine))
        f.check(same, f"block '{name}': cell point coordinates differ from the VTU's")
        used = len(set(np.concatenate(bcells).tolist())) if bcells else 0
        f.check(used == len(bpoints), f"block '{name}': {len(bpoints)} points, its cells use {used}")
        f.check(set(bdata["boundary_group"].tolist()) == {g}, f"block '{name}': boundary_group is not {g}")

    # Atomic: the piece folder's path is taken by a file; the run fails and leaves nothing.
    blocked = a.workdir + "_blocked"
    shutil.rmtree(blocked, ignore_errors=True)
    os.makedirs(blocked)
    with open(os.path.join(blocked, "coarse"), "w") as fh:
        fh.write("not a folder\n")
    failed = run(a.exe, a.config, blocked, ["vtm"])
    f.check(failed.returncode != 0, "a run whose piece folder is blocked must fail")
    f.check("coarse" in failed.stderr, f"the error names the path: {failed.stderr.strip()}")
    f.check(sorted(os.listdir(blocked)) == ["coarse"], f"a failed run left {sorted(os.listdir(blocked))}")
    with open(os.path.join(blocked, "coarse")) as fh:
        f.check(fh.read() == "not a folder\n", "the file at the folder's path was changed")
    f.finish("verify_vtm")


if __name__ == "__main__":
    main()
