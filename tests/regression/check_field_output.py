#!/usr/bin/env python3
"""Field output as ParaView reads it (issue: tensors in VTK's order, requests honoured and carried over).

  check_field_output.py --exe BIN --deck decks/single/field_output_shear.inp --out DIR

The deck prescribes u = H X on every node of one linear-elastic C3D8 (small strain, one increment per step), so
eps = sym(H) and sigma = lambda tr(eps) I + 2 mu eps exactly; H has all three shear components, so a tensor read in
the wrong component order (S13 taken as YZ) has other principal values. The frames are read with VTK (Debian's
python3-vtk9), whose 6-component convention is XX, YY, ZZ, XY, YZ, XZ, and compared with the closed form:
S, S_principal, Mises and LE to 1e-6 relative (the ASCII frames carry 9 significant digits). Step 2 has no output
request of its own: the request of step 1 (LE included) stays in effect, as in Abaqus. PEEQ cannot be written:
the run must warn with file and line.
"""
import argparse
import os
import subprocess
import sys
import xml.etree.ElementTree as ET

import numpy as np
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
from vtkmodules.util.numpy_support import vtk_to_numpy

H = 1e-3 * np.array([[1.0, 2.0, 3.0], [0.0, -0.5, 1.5], [1.0, 0.0, 2.0]])
E, NU = 1000.0, 0.3
LAM, MU = E * NU / ((1 + NU) * (1 - 2 * NU)), E / (2 * (1 + NU))
RTOL = 1e-6


def fail(msg):
    print("FAIL: " + msg)
    sys.exit(1)


def vtk_tensor(v):
    """A 6-component VTK array value as the 3x3 tensor VTK/ParaView take it to be (XX YY ZZ XY YZ XZ)."""
    xx, yy, zz, xy, yz, xz = v
    return np.array([[xx, xy, xz], [xy, yy, yz], [xz, yz, zz]])


def check(name, got, want):
    got, want = np.asarray(got, float), np.asarray(want, float)
    err = np.max(np.abs(got - want)) / max(1e-30, np.max(np.abs(want)))
    print("%-28s rel. error %.2e %s" % (name, err, "ok" if err <= RTOL else "FAIL"))
    if err > RTOL:
        fail("%s: got %s want %s" % (name, got, want))


def read_cells(path):
    r = vtkXMLUnstructuredGridReader()
    r.SetFileName(path)
    r.Update()
    cd = r.GetOutput().GetCellData()
    arrays = {cd.GetArrayName(i): cd.GetArray(i) for i in range(cd.GetNumberOfArrays())}
    return arrays


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    ap.add_argument("--deck", required=True)
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    p = subprocess.run([a.exe, "-q", "-o", a.out, a.deck], capture_output=True, text=True)
    if p.returncode != 0:
        fail("ldfcz exit %d: %s" % (p.returncode, p.stderr))
    job = os.path.splitext(os.path.basename(a.deck))[0]
    if not ("PEEQ" in p.stderr and os.path.basename(a.deck) + ":" in p.stderr):
        fail("no warning naming the file, line and PEEQ: " + p.stderr)
    print("warning for PEEQ: ok")
    pvd = ET.parse(os.path.join(a.out, job + ".pvd")).getroot()
    frames = [(float(d.get("timestep")), d.get("file")) for d in pvd.iter("DataSet")]
    if [t for t, _ in frames] != [0.0, 1.0, 2.0]:
        fail("PVD times %s, want total times 0, 1, 2" % [t for t, _ in frames])
    for scale, (t, f) in zip((1.0, 2.0), frames[1:]):
        arrays = read_cells(os.path.join(a.out, f))
        for need in ("S", "S_principal", "Mises", "LE"):
            if need not in arrays:
                fail("frame at t = %g has no %s (arrays: %s)" % (t, need, sorted(arrays)))
        eps = 0.5 * scale * (H + H.T)
        sig = LAM * np.trace(eps) * np.eye(3) + 2 * MU * eps
        s_vtk = vtk_tensor(vtk_to_numpy(arrays["S"])[0])
        check("S (t=%g)" % t, s_vtk, sig)
        check("LE (t=%g)" % t, vtk_tensor(vtk_to_numpy(arrays["LE"])[0]), eps)
        check("S_principal (t=%g)" % t, vtk_to_numpy(arrays["S_principal"])[0], np.linalg.eigvalsh(sig))
        # what a ParaView tensor filter computes from the array: the eigenvalues of the tensor as VTK reads it
        check("eig of S as VTK reads it", np.linalg.eigvalsh(s_vtk), np.linalg.eigvalsh(sig))
        dev = sig - np.trace(sig) / 3 * np.eye(3)
        check("Mises (t=%g)" % t, vtk_to_numpy(arrays["Mises"])[0], np.sqrt(1.5 * np.sum(dev * dev)))
        names = [arrays["S"].GetComponentName(k) for k in range(6)]
        if names != ["XX", "YY", "ZZ", "XY", "YZ", "XZ"]:
            fail("S component names %s" % names)
    print("field output: ok")


if __name__ == "__main__":
    main()
