#!/usr/bin/env python3
"""The VTU cell of every element type of the catalogue as VTK reads it (cell type and node order).

  check_vtu_cells.py --exe LDFCZ --tables LDFCZ_DOC_TABLES --out DIR

For each type that `ldfcz_doc_tables element-list` prints (the element catalogue, host/elements/element_catalog.f90)
one undistorted element (unit cube, tetrahedron or wedge on the unit corners; unit square, off the axis for CAX)
with mid-side nodes at the edge midpoints is run with *OUTPUT, FIELD, and its last frame read with VTK
(python3-vtk9): the cell must have the VTK type VTK defines for that node layout (hexahedron 12, 20-node
hexahedron 25, tetrahedron 10, 10-node tetrahedron 24, wedge 13, quadrilateral 9, 8-node quadrilateral 23,
triangle 5, 6-node triangle 22, 15-node wedge 26), a positive size from VTK's own vtkCellSizeFilter equal to the element's (1, 1/6
or 1/2 in 3D, 1 or 1/2 in 2D, on the
frame's points, the original coordinates; to 1e-7 relative, the precision of the ASCII frames), and in 3D every face of VTK's cell must point outward (normal . (face centre - cell centre) > 0): a node
order that is not VTK's (the wedge's base triangle, which VTK orders clockwise seen from the top while Abaqus
numbers it counter-clockwise) gives a negative size or inward faces.
"""
import argparse
import os
import subprocess
import sys

import numpy as np
from vtkmodules.vtkCommonCore import vtkIdList, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkUnstructuredGrid
from vtkmodules.vtkFiltersVerdict import vtkCellSizeFilter
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader

VTK_CELL = {(8, 3): 12, (20, 3): 25, (4, 3): 10, (10, 3): 24, (6, 3): 13, (4, 2): 9, (8, 2): 23, (3, 2): 5,
            (6, 2): 22, (15, 3): 26}
HEX = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
HEX_EDGES = [(1, 2), (2, 3), (3, 4), (4, 1), (5, 6), (6, 7), (7, 8), (8, 5), (1, 5), (2, 6), (3, 7), (4, 8)]
TET = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
TET_EDGES = [(1, 2), (2, 3), (3, 1), (1, 4), (2, 4), (3, 4)]
WEDGE = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (0, 1, 1)]
WEDGE_EDGES = [(1, 2), (2, 3), (3, 1), (4, 5), (5, 6), (6, 4), (1, 4), (2, 5), (3, 6)]
QUAD = [(0, 0), (1, 0), (1, 1), (0, 1)]
QUAD_EDGES = [(1, 2), (2, 3), (3, 4), (4, 1)]
TRI = [(0, 0), (1, 0), (0, 1)]
TRI_EDGES = [(1, 2), (2, 3), (3, 1)]


def fail(msg):
    print("FAIL: " + msg)
    sys.exit(1)


def element_nodes(name, nnode, ndim):
    """Abaqus-ordered nodes of one undistorted element and its size (volume or area)."""
    if ndim == 3:
        corners, edges, size = {8: (HEX, [], 1.0), 20: (HEX, HEX_EDGES, 1.0), 4: (TET, [], 1 / 6),
                                10: (TET, TET_EDGES, 1 / 6), 6: (WEDGE, [], 0.5), 15: (WEDGE, WEDGE_EDGES, 0.5)}[nnode]
    else:
        corners, edges, size = {4: (QUAD, [], 1.0), 8: (QUAD, QUAD_EDGES, 1.0), 3: (TRI, [], 0.5),
                                6: (TRI, TRI_EDGES, 0.5)}[nnode]
        if name.startswith("CAX"):
            corners = [(1.0 + p[0], p[1]) for p in corners]
    x = [tuple(float(c) for c in p) for p in corners]
    for a, b in edges:
        x.append(tuple(0.5 * (p + q) for p, q in zip(x[a - 1], x[b - 1])))
    return x, size


def deck(path, name, x):
    nd = len(x[0])
    out = ["*HEADING", "one %s, every node on u = 1e-3 X (tests/regression/check_vtu_cells.py)" % name,
           "*NODE, NSET=ALL"]
    out += ["%d, %s" % (i + 1, ", ".join("%.15g" % c for c in p)) for i, p in enumerate(x)]
    out += ["*ELEMENT, TYPE=%s, ELSET=E" % name]
    ids = [str(i + 1) for i in range(len(x))]
    out += ["1, " + ", ".join(ids[:15]) + ("," if len(ids) > 15 else "")]
    if len(ids) > 15:
        out += [", ".join(ids[15:])]
    out += ["*SOLID SECTION, ELSET=E, MATERIAL=M", "*MATERIAL, NAME=M", "*ELASTIC", "1000., 0.3",
            "*STEP", "*STATIC", "1., 1.", "*BOUNDARY"]
    for i, p in enumerate(x):
        for d in range(nd):
            out.append("%d, %d, %d, %.15g" % (i + 1, d + 1, d + 1, 1e-3 * p[d]))
    out += ["*OUTPUT, FIELD", "*ELEMENT OUTPUT", "S", "*END STEP"]
    with open(path, "w") as f:
        f.write("\n".join(out) + "\n")


def check_frame(path, name, nnode, ndim, size, want_cell):
    r = vtkXMLUnstructuredGridReader()
    r.SetFileName(path)
    r.Update()
    g = r.GetOutput()
    if g.GetNumberOfCells() != 1:
        fail("%s: %d cells in %s" % (name, g.GetNumberOfCells(), path))
    cell = g.GetCell(0)
    if g.GetCellType(0) != want_cell or cell.GetNumberOfPoints() != nnode:
        fail("%s: VTK cell type %d with %d points, expected %d with %d" % (name, g.GetCellType(0),
                                                                         cell.GetNumberOfPoints(), want_cell, nnode))
    # VTK's size of the cell on the undeformed points (the frame's points are the original coordinates)
    pts = vtkPoints()
    for k in range(g.GetNumberOfPoints()):
        pts.InsertNextPoint(g.GetPoint(k))
    ug = vtkUnstructuredGrid()
    ug.SetPoints(pts)
    ids = vtkIdList()
    for k in range(cell.GetNumberOfPoints()):
        ids.InsertNextId(cell.GetPointId(k))
    ug.InsertNextCell(want_cell, ids)
    f = vtkCellSizeFilter()
    f.SetInputData(ug)
    f.Update()
    got = f.GetOutput().GetCellData().GetArray("Volume" if ndim == 3 else "Area").GetValue(0)
    if abs(got - size) > 1e-7 * size:
        fail("%s: VTK's cell size %.9g, the element's %.9g (node order not VTK's)" % (name, got, size))
    inward = []
    if ndim == 3:
        p = np.array([ug.GetPoint(ug.GetCell(0).GetPointId(k)) for k in range(nnode)])
        c = ug.GetCell(0)
        for fi in range(c.GetNumberOfFaces()):
            fc = c.GetFace(fi)
            fp = np.array([ug.GetPoint(fc.GetPointId(j)) for j in range(fc.GetNumberOfPoints())])
            n = np.cross(fp[1] - fp[0], fp[2] - fp[0])
            if np.dot(n, fp.mean(axis=0) - p.mean(axis=0)) <= 0:
                inward.append(fi)
    if inward:
        fail("%s: VTK faces %s point into the cell" % (name, inward))
    print("%-7s VTK cell %2d, %2d points, size %.6g%s: ok" % (name, want_cell, nnode, got,
                                                              ", faces outward" if ndim == 3 else ""))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    ap.add_argument("--tables", required=True)
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    listing = subprocess.run([a.tables, "element-list"], capture_output=True, text=True, check=True).stdout
    types = [line.split() for line in listing.splitlines() if line.strip()]
    if not types:
        fail("ldfcz_doc_tables listed no element type")
    for name, nnode, ndim, vtk in types:
        nnode, ndim, vtk = int(nnode), int(ndim), int(vtk)
        want = VTK_CELL.get((nnode, ndim))
        if want is None or vtk != want:
            fail("%s: the catalogue gives VTK cell %d, VTK's cell of %d nodes in %dD is %s" % (name, vtk, nnode, ndim,
                                                                                               want))
        x, size = element_nodes(name, nnode, ndim)
        job = name.lower()
        deck(os.path.join(a.out, job + ".inp"), name, x)
        res = subprocess.run([a.exe, "-q", job + ".inp"], cwd=a.out, capture_output=True, text=True)
        if res.returncode != 0:
            fail("%s: ldfcz exited with %d: %s" % (name, res.returncode, res.stdout + res.stderr))
        check_frame(os.path.join(a.out, job + "_0002.vtu"), name, nnode, ndim, size, want)
    print("PASS: %d element types" % len(types))


if __name__ == "__main__":
    main()
