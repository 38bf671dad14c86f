#!/usr/bin/env python3
"""The field frames as ParaView and the renderer read them (issue 37 item 3; docs/host.md, "Frames"):

  check_frames.py --exe LDFCZ --decks DECKS --root SRC --out DIR

1. Blocks: a model of continuum and user elements (decks/single/cohesive_block.inp) writes every frame as
   JOB_NNNN.vtm with the blocks continuum and interface (JOB.pvd lists the .vtm): the continuum block holds every
   continuum element once and no user element, with S, Mises, S_nodal; the interface block every user element
   once, with opening, traction, Delta_max and damage and none of the continuum's arrays; VTK's multiblock
   reader opens the .vtm. damage = 1 - exp(-Delta_max/delta) in every cell (uniform mode I: every point alike;
   2e-8: the frames hold 9 significant digits, es16.8).
2. Nodal averages: each patch deck (decks/patch: distorted C3D8, C3D8 small strain, C3D6, CPE4 meshes under a
   homogeneous deformation) with LE requested: S_nodal and LE_nodal at every node equal the element values, which
   are constant over the patch (2e-8 of the largest component: the frames' 9 digits; the extrapolation is exact
   for a constant, the patch holds to the Newton tolerance).
3. Pictures: render_frame.py without $DISPLAY (xvfb-run) on the cohesive block (3D, Mises and damage) and on a
   plane-strain peel scene (Mises, damage): every PNG of the asked size and not blank (at least 1 % of the model
   area coloured, 0.2 % for the plane interface drawn as a line; the peel's varying fields at least 6 and 4 hue
   bins of 24). The interface as drawn: with a continuum field the mid-surface of the
   cells that still hold only (damage < 0.99: the separated cells of the peeled flap are not drawn), with an
   interface field the bottom face of every cell, on the deformed bottom nodes (1e-12 mm).
"""
import argparse
import math
import os
import re
import shutil
import subprocess
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader
from vtkmodules.vtkIOXML import vtkXMLMultiBlockDataReader, vtkXMLUnstructuredGridReader

from ldfcz_tools import outputs, render_frame


def fail(msg):
    print("FAIL: " + msg)
    sys.exit(1)


def run(cmd, cwd=None, env=None):
    p = subprocess.run(cmd, capture_output=True, text=True, cwd=cwd, env=env, timeout=600)
    if p.returncode != 0:
        fail("%s: exit %d\n%s" % (" ".join(cmd), p.returncode, (p.stdout + p.stderr)[-3000:]))
    return p


def grid_arrays(path):
    r = vtkXMLUnstructuredGridReader()
    r.SetFileName(path)
    r.Update()
    g = r.GetOutput()
    cells = {g.GetCellData().GetArrayName(k): vtk_to_numpy(g.GetCellData().GetArray(k))
             for k in range(g.GetCellData().GetNumberOfArrays())}
    points = {g.GetPointData().GetArrayName(k): vtk_to_numpy(g.GetPointData().GetArray(k))
              for k in range(g.GetPointData().GetNumberOfArrays())}
    conn = [[g.GetCell(c).GetPointId(k) for k in range(g.GetCell(c).GetNumberOfPoints())]
            for c in range(g.GetNumberOfCells())]
    return cells, points, conn


def case_blocks(a):
    out = os.path.join(a.out, "blocks")
    deck = os.path.join(a.decks, "single", "cohesive_block.inp")
    run([a.exe, "-q", "-o", out, deck])
    job = "cohesive_block"
    frames = outputs.pvd_frames(os.path.join(out, job + ".pvd"))
    if not frames or not all(f.endswith(".vtm") for _, f in frames):
        fail("JOB.pvd lists %s, .vtm frames expected" % [f for _, f in frames])
    text = open(deck).read()
    delta = float(re.search(r"\*UEL PROPERTY[^\n]*\n\s*([^,\n]+),\s*([^,\n]+)", text, re.I).group(2))
    for _, f in frames:
        blocks = outputs.frame_files(os.path.join(out, f))
        if sorted(blocks) != ["continuum", "interface"]:
            fail("%s: blocks %s" % (f, sorted(blocks)))
        cc, cp, _ = grid_arrays(blocks["continuum"][0])
        ic, ip, _ = grid_arrays(blocks["interface"][0])
        if (cc["cohesive"] != 0).any() or (ic["cohesive"] != 1).any():
            fail("%s: a user element in the continuum block or a continuum element in the interface block" % f)
        if len(set(cc["element"]) & set(ic["element"])) or len(set(cc["element"])) != len(cc["element"]):
            fail("%s: an element in both blocks or twice" % f)
        for name in ("S", "Mises"):
            if name not in cc or name in ic:
                fail("%s: %s should be in the continuum block only" % (f, name))
        for name in ("opening", "traction", "Delta_max", "damage"):
            if name not in ic or name in cc:
                fail("%s: %s should be in the interface block only" % (f, name))
        if "S_nodal" not in cp or "S_nodal" in ip:
            fail("%s: S_nodal should be in the continuum block's point data only" % f)
        want = 1.0 - np.exp(-ic["Delta_max"] / delta)
        if np.abs(ic["damage"] - want).max() > 2e-8:
            fail("%s: damage %s against 1 - exp(-Delta_max/delta) %s" % (f, ic["damage"], want))
    r = vtkXMLMultiBlockDataReader()
    r.SetFileName(os.path.join(out, frames[-1][1]))
    r.Update()
    mb = r.GetOutput()
    names = [mb.GetMetaData(i).Get(mb.NAME()) for i in range(mb.GetNumberOfBlocks())]
    if names != ["continuum", "interface"] or mb.GetBlock(1).GetNumberOfCells() != len(ic["element"]):
        fail("VTK reads the .vtm as blocks %s" % names)
    print("blocks: %d frames, each JOB_NNNN.vtm of continuum (%d cells) and interface (%d cells); damage = "
          "1 - exp(-Delta_max/delta) (last frame %.6f)" % (len(frames), len(cc["element"]), len(ic["element"]),
                                                         ic["damage"].max()))
    return out


def case_nodal(a):
    for name in ("patch_c3d8", "patch_c3d8_linear", "patch_c3d6", "patch_cpe4"):
        src = os.path.join(a.decks, "patch", name + ".inp")
        out = os.path.join(a.out, "nodal", name)
        os.makedirs(out, exist_ok=True)
        text = open(src).read()
        k = text.upper().rindex("*END STEP")
        deck = os.path.join(out, name + ".inp")
        with open(deck, "w") as f:
            f.write(text[:k] + "*OUTPUT, FIELD\n*ELEMENT OUTPUT\nS, LE\n" + text[k:])
        run([a.exe, "-q", "-o", out, deck])
        frames = outputs.pvd_frames(os.path.join(out, name + ".pvd"))
        blocks = outputs.frame_files(os.path.join(out, frames[-1][1]))
        cells, points, conn = grid_arrays(blocks[""][0])
        used = sorted(set(p for c in conn for p in c))
        worst = 0.0
        for nodal, elem in (("S_nodal", "S"), ("LE_nodal", "LE")):
            e = cells[elem]
            scale = max(np.abs(e).max(), 1e-300)
            if np.abs(e - e[0]).max() > 2e-8 * scale:
                fail("%s: %s is not homogeneous over the patch (%g)" % (name, elem, np.abs(e - e[0]).max() / scale))
            d = np.abs(points[nodal][used] - e[0]).max() / scale
            worst = max(worst, d)
            if d > 2e-8:
                fail("%s: %s at the nodes differs from the patch's constant %s by %.2e of its largest component"
                     % (name, nodal, elem, d))
        print("nodal averages: %-18s %d nodes, S_nodal and LE_nodal = the constant S, LE to %.1e" % (
            name, len(used), worst))


def image_stats(path, size):
    """Share of coloured pixels and the hue bins among them, in the picture's model area (left 84 %, below the
    title: render_frame's viewport; the colour bar to its right always holds every hue)."""
    r = vtkPNGReader()
    r.SetFileName(path)
    r.Update()
    img = r.GetOutput()
    w, h, _ = img.GetDimensions()
    if (w, h) != size:
        fail("%s: %dx%d pixels, %dx%d asked" % (path, w, h, size[0], size[1]))
    rgb = vtk_to_numpy(img.GetPointData().GetScalars())[:, :3].astype(int).reshape(h, w, 3)
    rgb = rgb[:int(0.92 * h), :int(0.84 * w)].reshape(-1, 3)   # rows from the bottom in VTK's images
    white = (rgb >= 250).all(axis=1)
    grey = (np.abs(rgb[:, 0] - rgb[:, 1]) < 10) & (np.abs(rgb[:, 1] - rgb[:, 2]) < 10)
    coloured = ~white & ~grey
    hues = set()
    for px in rgb[coloured][::7]:
        r_, g_, b_ = px / 255.0
        mx, mn = max(r_, g_, b_), min(r_, g_, b_)
        if mx - mn < 0.2:
            continue
        if mx == r_:
            hue = ((g_ - b_) / (mx - mn)) % 6
        elif mx == g_:
            hue = (b_ - r_) / (mx - mn) + 2
        else:
            hue = (r_ - g_) / (mx - mn) + 4
        hues.add(int(hue * 4))   # 24 hue bins
    return coloured.mean(), len(hues)


def case_pictures(a, blocks_out):
    peel = os.path.join(a.out, "peel")
    os.makedirs(peel, exist_ok=True)
    deck = os.path.join(peel, "small_peel.inp")
    run([sys.executable, os.path.join(a.root, "tools", "peel_deck.py"), "--rigid-substrate", "--reading", "peel",
         "--flap", "0.1", "--grip", "carriage", "--u-total", "0.05", "--fine-length", "0.1", "--le", "0.02",
         "--nz", "2", "-o", deck])
    run([a.exe, "-q", "-o", peel, deck])
    env = dict(os.environ)
    env.pop("DISPLAY", None)   # headless: the command must find its X server (xvfb-run) itself
    render = [sys.executable, os.path.join(a.root, "tools", "render_frame.py")]
    # (field, the least share of coloured pixels in the model area: 1 % for surfaces, 0.2 % for the plane peel's
    # interface, a line of 4 pixels over half the width; the least hue bins of 24: the peel's Mises 0..38 MPa and
    # damage 0..1 spread over the map, the block's fields are nearly uniform: one colour)
    for run_dir, field, area, least in ((blocks_out, "Mises", 0.01, 1), (blocks_out, "damage", 0.01, 1),
                                        (peel, "Mises", 0.01, 6), (peel, "damage", 0.002, 4)):
        png = os.path.join(a.out, "%s_%s.png" % (os.path.basename(run_dir), field))
        p = run(render + [run_dir, "--field", field, "--size", "800x600", "-o", png], env=env)
        share, hues = image_stats(png, (800, 600))
        print("picture: %-22s %4.1f %% of the pixels coloured, %2d hues  (%s)" % (
            os.path.basename(png), 100 * share, hues, p.stdout.strip()))
        if share < area or hues < least:
            fail("%s: blank or one colour (%.3f coloured, %d hues)" % (png, share, hues))
    # the interface as drawn: mid-surface of the cells that hold only; the bottom face of every cell
    frames = outputs.pvd_frames(os.path.join(peel, "small_peel.pvd"))
    _, interface = render_frame.read_blocks(os.path.join(peel, frames[-1][1]))
    dmg = vtk_to_numpy(interface.GetCellData().GetArray("damage"))
    mid = render_frame.interface_geometry(interface, "auto", False, 1.0)
    if mid.GetNumberOfCells() != int((dmg < 0.99).sum()) or (dmg >= 0.99).sum() == 0:
        fail("mid-surface: %d cells drawn, %d hold, %d separated" % (mid.GetNumberOfCells(), (dmg < 0.99).sum(),
                                                                     (dmg >= 0.99).sum()))
    bottom = render_frame.interface_geometry(interface, "auto", True, 1.0)
    x = vtk_to_numpy(interface.GetPoints().GetData()) + vtk_to_numpy(interface.GetPointData().GetArray("U"))
    ends = sorted({tuple(np.round(x[interface.GetCell(c).GetPointId(k)], 12)) for c in
                   range(interface.GetNumberOfCells()) for k in (0, 1)})
    got = vtk_to_numpy(bottom.GetPoints().GetData())
    off = max(min(math.dist(p, q) for q in ends) for p in got)
    if bottom.GetNumberOfCells() != interface.GetNumberOfCells() or off > 1e-12:
        fail("bottom face: %d of %d cells, %.2e mm off the bottom nodes" % (bottom.GetNumberOfCells(),
                                                                          interface.GetNumberOfCells(), off))
    print("interface drawn: mid-surface of the %d cells that hold (%d separated left out); bottom face of all %d, "
          "on the bottom nodes to %.1e mm" % (mid.GetNumberOfCells(), (dmg >= 0.99).sum(),
                                              bottom.GetNumberOfCells(), off))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    ap.add_argument("--decks", required=True)
    ap.add_argument("--root", required=True)
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    a.exe, a.out, a.decks, a.root = (os.path.abspath(x) for x in (a.exe, a.out, a.decks, a.root))
    shutil.rmtree(a.out, ignore_errors=True)
    os.makedirs(a.out)
    blocks_out = case_blocks(a)
    case_nodal(a)
    case_pictures(a, blocks_out)
    print("PASS")


if __name__ == "__main__":
    main()
