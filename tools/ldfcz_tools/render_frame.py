"""Render a field frame of a run to a PNG, on a headless machine too (docs/tools.md, "Looking at results").

  render_frame.py RUN [-o OUT.png] [--field NAME] [--frame N | --time T] [--scale S] [--view VIEW]

RUN is a run's output directory (its JOB.pvd), a JOB.pvd, or one frame (.vtm, .vtu, .pvtu). The picture: the
continuum elements' outer surface on the deformed mesh (displacements x --scale, default 1), coloured by --field:
  Mises (default)            von Mises stress of S_nodal (the stress extrapolated to and averaged at the nodes:
                             smooth contours), or of the element values with --cells
  S11 S22 S33 S12 S13 S23    a component of S (nodal, or --cells); LE11 .. LE23 likewise of LE (when requested)
  U, U1, U2, U3              displacement magnitude or component
  opening, damage, Delta_max, traction   the interface elements' values (the continuum then drawn in grey)
The interface (user) elements are never drawn as the cell between their two faces by default, so a broken
interface does not cover the picture with a large solid wedge: with a continuum field their deformed mid-surface
(a line in 2D) where they still hold (damage < 0.99), with an interface field their bottom face (the first face of
the COH3D8/COH2D4 layout, the substrate's side in the peel scenes) coloured by it. --interface mid-all, bottom,
hide or cells (the cells as they are) choose otherwise. --view xy (default for a plane model: z = 0
everywhere), xz, yz or iso (default in 3D). --frame N picks the N-th frame of JOB.pvd (1 = first, -1 = last,
the default), --time T the frame nearest to total time T.

Needs VTK (Debian: python3-vtk9, for /usr/bin/python3; a python3 without it restarts the command under
/usr/bin/python3) and, as Debian's VTK renders off-screen through X, an X server: without $DISPLAY the command
starts itself again under xvfb-run (Debian: xvfb and xauth; tools/setup.sh installs them). Exit 2 with one line
when something is missing or the input is not a frame.
"""
import argparse
import math
import os
import shutil
import sys
import xml.etree.ElementTree as ET

from ldfcz_tools.cli import ToolError, reexec

#: Python modules the command needs (ldfcz_tools.cli checks them before main)
REQUIRES = ('vtkmodules',)

INTERFACE_FIELDS = ('opening', 'damage', 'Delta_max', 'traction')
TENSOR = {'11': 0, '22': 1, '33': 2, '12': 3, '23': 4, '13': 5}   # VTK's component order XX YY ZZ XY YZ XZ


def parse(argv):
    ap = argparse.ArgumentParser(prog='render_frame.py', description=__doc__.split('\n')[0])
    ap.add_argument('run', help='output directory, JOB.pvd, or a frame (.vtm, .vtu, .pvtu)')
    ap.add_argument('-o', '--output', default='', help='PNG to write (default: FRAME.png beside the frame)')
    ap.add_argument('--field', default='Mises')
    ap.add_argument('--cells', action='store_true', help='element values instead of the nodal averages')
    g = ap.add_mutually_exclusive_group()
    g.add_argument('--frame', type=int, default=-1, help='frame of JOB.pvd: 1 the first, -1 the last (default)')
    g.add_argument('--time', type=float, default=None, help='the frame nearest to this total time')
    ap.add_argument('--scale', type=float, default=1.0, help='displacement scale (default 1: true deformation)')
    ap.add_argument('--view', choices=('auto', 'xy', 'xz', 'yz', 'iso'), default='auto')
    ap.add_argument('--interface', choices=('auto', 'mid', 'mid-all', 'bottom', 'hide', 'cells'), default='auto',
                    help='how the interface elements are drawn (default: the mid-surface of the cells that still '
                    'hold with a continuum field, the bottom face coloured with an interface field)')
    ap.add_argument('--size', default='1200x800', help='image size WxH in pixels (default 1200x800)')
    ap.add_argument('--edges', choices=('auto', 'on', 'off'), default='auto',
                    help='element edges (auto: on below 20000 cells)')
    return ap.parse_args(argv)


def frame_file(run, frame, time):
    """The frame file a RUN argument names (see the module doc), and its total time (None when unknown)."""
    if os.path.isdir(run):
        pvds = sorted(f for f in os.listdir(run) if f.endswith('.pvd'))
        if len(pvds) != 1:
            raise ToolError('%s: %s JOB.pvd in this directory (give the .pvd or a frame file)' % (
                run, 'no' if not pvds else 'more than one'))
        run = os.path.join(run, pvds[0])
    if not os.path.exists(run):
        raise ToolError('%s: no such file or directory' % run)
    if run.endswith(('.vtm', '.vtu', '.pvtu')):
        return run, None
    try:
        root = ET.parse(run).getroot()
    except ET.ParseError as e:
        raise ToolError('%s: not a ParaView collection (.pvd) or frame: %s' % (run, e)) from None
    except UnicodeDecodeError:
        raise ToolError('%s: not a ParaView collection (.pvd) or frame (a binary file?)' % run) from None
    sets = [(float(d.get('timestep', 'nan')), d.get('file')) for d in root.iter('DataSet') if d.get('file')]
    if not sets:
        raise ToolError('%s: lists no frame (JOB.pvd of a run with *OUTPUT, FIELD expected)' % run)
    if time is not None:
        t, f = min(sets, key=lambda s: abs(s[0] - time))
    else:
        if frame == 0 or abs(frame) > len(sets):
            raise ToolError('%s: frame %d asked, it lists %d' % (run, frame, len(sets)))
        t, f = sets[frame - 1 if frame > 0 else frame]
    path = os.path.join(os.path.dirname(run), f)
    if not os.path.exists(path):
        raise ToolError('%s: frame file %s is missing' % (run, path))
    return path, t


def read_blocks(path):
    """(continuum, interface) unstructured grids of a frame (either may be None)."""
    from vtkmodules.vtkIOXML import (vtkXMLMultiBlockDataReader, vtkXMLPUnstructuredGridReader,
                                     vtkXMLUnstructuredGridReader)
    from vtkmodules.vtkCommonDataModel import vtkMultiBlockDataSet
    if path.endswith('.vtm'):
        r = vtkXMLMultiBlockDataReader()
    elif path.endswith('.pvtu'):
        r = vtkXMLPUnstructuredGridReader()
    else:
        r = vtkXMLUnstructuredGridReader()
    if not r.CanReadFile(path):
        raise ToolError('%s: not a VTK XML frame file' % path)
    r.SetFileName(path)
    r.Update()
    out = r.GetOutput()
    grids = []
    if isinstance(out, vtkMultiBlockDataSet):
        for i in range(out.GetNumberOfBlocks()):
            name = out.GetMetaData(i).Get(vtkMultiBlockDataSet.NAME()) if out.HasMetaData(i) else ''
            if out.GetBlock(i) is not None:
                grids.append((name, merged(out.GetBlock(i))))
    else:
        grids.append(('', out))
    continuum = interface = None
    for name, g in grids:
        if g.GetNumberOfCells() == 0:
            continue
        coh = g.GetCellData().GetArray('cohesive')
        if name == 'interface' or (coh is not None and coh.GetRange()[0] >= 1):
            interface = g
        elif coh is not None and coh.GetRange()[1] >= 1:
            # a frame of one block holding both kinds (ldfcz before the interface block): split on the flag
            continuum, interface = split_on_flag(g)
        else:
            continuum = g
    if continuum is None and interface is None:
        raise ToolError('%s: the frame holds no cells' % path)
    return continuum, interface


def merged(block):
    """A block as one grid: a distributed run's block of process pieces appended, shared points merged."""
    from vtkmodules.vtkCommonDataModel import vtkMultiBlockDataSet
    from vtkmodules.vtkFiltersCore import vtkAppendFilter
    if not isinstance(block, vtkMultiBlockDataSet):
        return block
    app = vtkAppendFilter()
    app.MergePointsOn()
    for i in range(block.GetNumberOfBlocks()):
        if block.GetBlock(i) is not None:
            app.AddInputData(merged(block.GetBlock(i)))
    app.Update()
    return app.GetOutput()


def split_on_flag(g):
    from vtkmodules.vtkFiltersCore import vtkThreshold
    parts = []
    for lo, hi in ((-0.5, 0.5), (0.5, 1.5)):
        t = vtkThreshold()
        t.SetInputData(g)
        t.SetInputArrayToProcess(0, 0, 0, 1, 'cohesive')
        t.SetLowerThreshold(lo)
        t.SetUpperThreshold(hi)
        t.Update()
        parts.append(t.GetOutput() if t.GetOutput().GetNumberOfCells() else None)
    return parts[0], parts[1]


def field_values(grid, field, cells):
    """(association 'point' or 'cell', list of values, label) of a field on a grid; ToolError when absent."""
    from vtkmodules.util.numpy_support import vtk_to_numpy
    import numpy as np

    def arr(kind, name):
        data = grid.GetPointData() if kind == 'point' else grid.GetCellData()
        a = data.GetArray(name)
        return None if a is None else vtk_to_numpy(a).astype(float)

    def mises(s):
        return np.sqrt(0.5 * ((s[:, 0] - s[:, 1]) ** 2 + (s[:, 1] - s[:, 2]) ** 2 + (s[:, 2] - s[:, 0]) ** 2)
                       + 3.0 * (s[:, 3] ** 2 + s[:, 4] ** 2 + s[:, 5] ** 2))
    f = field
    if f in INTERFACE_FIELDS:
        a = arr('cell', f)
        if a is None:
            raise ToolError('the frame has no %r array on the interface elements' % f)
        return 'cell', np.linalg.norm(a, axis=1) if a.ndim > 1 else a, f + (' (mm)' if f in ('opening', 'Delta_max')
                                                                             else ' (MPa)' if f == 'traction' else '')
    if f == 'U' or (len(f) == 2 and f[0] == 'U' and f[1] in '123'):
        u = arr('point', 'U')
        if u is None:
            raise ToolError('the frame has no U array')
        return 'point', (np.linalg.norm(u, axis=1) if f == 'U' else u[:, int(f[1]) - 1]), f + ' (mm)'
    if f == 'Mises':
        s = None if cells else arr('point', 'S_nodal')
        if s is not None:
            return 'point', mises(s), 'Mises of S averaged at the nodes (MPa)'
        a = arr('cell', 'Mises')
        if a is None:
            raise ToolError('the frame has no Mises or S_nodal array (no continuum elements?)')
        return 'cell', a, 'Mises, element mean (MPa)'
    for tensor, unit in (('S', 'MPa'), ('LE', '-')):
        if f.startswith(tensor) and f[len(tensor):] in TENSOR:
            k = TENSOR[f[len(tensor):]]
            s = None if cells else arr('point', tensor + '_nodal')
            if s is not None:
                return 'point', s[:, k], '%s averaged at the nodes (%s)' % (f, unit)
            a = arr('cell', tensor)
            if a is None:
                raise ToolError('the frame has no %s array%s' % (tensor, ' (request LE in *ELEMENT OUTPUT)' if
                                                                    tensor == 'LE' else ''))
            return 'cell', a[:, k], '%s, element mean (%s)' % (f, unit)
    raise ToolError('unknown field %r (Mises, S11..S23, LE11..LE23, U, U1..U3, %s)' % (
        field, ', '.join(INTERFACE_FIELDS)))


def deformed(grid, scale):
    """The grid with its points moved by scale x U (U absent: as it is)."""
    from vtkmodules.vtkFiltersGeneral import vtkWarpVector
    if grid.GetPointData().GetArray('U') is None:
        return grid
    grid.GetPointData().SetActiveVectors('U')
    w = vtkWarpVector()
    w.SetInputData(grid)
    w.SetScaleFactor(scale)
    w.Update()
    return w.GetOutput()


def mid_surface(grid, scale, top_weight=0.5, keep=None):
    """The interface elements as a deformed surface between their two faces: a quadrilateral of an 8-node cell
    (COH3D8 layout: points 0-3 bottom, 4-7 top), a line of a 4-node one (COH2D4: 0-1 bottom, 3 over 0 and 2 over 1),
    at top_weight between the bottom (0) and the top face (1; 0.5: the mid-surface), with the cells' data; only the
    cells c with keep[c] (all when keep is None)."""
    from vtkmodules.vtkCommonCore import vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
    pts_in = grid.GetPoints()
    u = grid.GetPointData().GetArray('U')

    def x(i):
        p = pts_in.GetPoint(i)
        d = u.GetTuple3(i) if u is not None else (0.0, 0.0, 0.0)
        return [p[k] + scale * d[k] for k in range(3)]
    pts, polys, lines, keep_poly, keep_line = vtkPoints(), vtkCellArray(), vtkCellArray(), [], []
    pts.SetDataTypeToDouble()
    for c in range(grid.GetNumberOfCells()):
        if keep is not None and not keep[c]:
            continue
        ids = grid.GetCell(c).GetPointIds()
        n = ids.GetNumberOfIds()
        if n == 8:
            pairs = [(ids.GetId(k), ids.GetId(k + 4)) for k in range(4)]
        elif n == 4:
            pairs = [(ids.GetId(0), ids.GetId(3)), (ids.GetId(1), ids.GetId(2))]
        else:
            continue
        first = pts.GetNumberOfPoints()
        for a, b in pairs:
            xa, xb = x(a), x(b)
            pts.InsertNextPoint([(1.0 - top_weight) * xa[k] + top_weight * xb[k] for k in range(3)])
        target = polys if n == 8 else lines
        target.InsertNextCell(len(pairs))
        for k in range(len(pairs)):
            target.InsertCellPoint(first + k)
        (keep_poly if n == 8 else keep_line).append(c)
    pd = vtkPolyData()
    pd.SetPoints(pts)
    pd.SetPolys(polys)
    pd.SetLines(lines)
    # cell data in VTK's order for polydata: vertices, lines, polygons
    order = keep_line + keep_poly
    cd = grid.GetCellData()
    for k in range(cd.GetNumberOfArrays()):
        src = cd.GetArray(k)
        dst = src.NewInstance()
        dst.SetName(src.GetName())
        dst.SetNumberOfComponents(src.GetNumberOfComponents())
        for c in order:
            dst.InsertNextTuple(src.GetTuple(c))
        pd.GetCellData().AddArray(dst)
    return pd


def interface_geometry(interface, mode, on_interface, scale):
    """What is drawn of the interface elements (mode: see --interface; auto: 'bottom' for an interface field, else
    'mid', the mid-surface of the cells that still hold, damage < 0.99, where the frame has damage)."""
    if mode == 'auto':
        mode = 'bottom' if on_interface else 'mid'
    if mode == 'cells':
        return deformed(interface, scale)
    if mode == 'bottom':
        return mid_surface(interface, scale, 0.0)
    # a separated cell's mid-surface lies in the gap between the two bodies: only the cells that hold
    dmg = interface.GetCellData().GetArray('damage')
    keep = None if dmg is None or mode == 'mid-all' else \
        [dmg.GetTuple1(c) < 0.99 for c in range(interface.GetNumberOfCells())]
    return mid_surface(interface, scale, 0.5, keep)


def actor_of(data, assoc=None, values=None, rng=None, color=(0.75, 0.75, 0.75), edges=False, width=1.0):
    """An actor of data's outer surface, coloured by values (per point or cell of data) over rng, or plain."""
    from vtkmodules.vtkFiltersGeometry import vtkDataSetSurfaceFilter
    from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper
    from vtkmodules.util.numpy_support import numpy_to_vtk
    if values is not None:
        arr = numpy_to_vtk(values, deep=True)
        arr.SetName('_field')
        (data.GetPointData() if assoc == 'point' else data.GetCellData()).AddArray(arr)
    surf = vtkDataSetSurfaceFilter()
    surf.SetInputData(data)
    surf.Update()
    mapper = vtkPolyDataMapper()
    mapper.SetInputData(surf.GetOutput())
    if values is not None:
        if assoc == 'point':
            mapper.SetScalarModeToUsePointFieldData()
        else:
            mapper.SetScalarModeToUseCellFieldData()
        mapper.SelectColorArray('_field')
        lut = rainbow()
        lut.SetRange(*rng)
        mapper.SetLookupTable(lut)
        mapper.UseLookupTableScalarRangeOn()
        mapper.ScalarVisibilityOn()
    else:
        mapper.ScalarVisibilityOff()
    act = vtkActor()
    act.SetMapper(mapper)
    act.GetProperty().SetAmbient(0.45)
    act.GetProperty().SetDiffuse(0.6)
    if values is None:
        act.GetProperty().SetColor(*color)
    if edges:
        act.GetProperty().EdgeVisibilityOn()
        act.GetProperty().SetEdgeColor(0.15, 0.15, 0.15)
    act.GetProperty().SetLineWidth(width)
    return act


def rainbow():
    """Blue to red, as Abaqus/CAE's default contour spectrum."""
    from vtkmodules.vtkCommonCore import vtkLookupTable
    lut = vtkLookupTable()
    lut.SetHueRange(0.667, 0.0)
    lut.SetNumberOfTableValues(12)
    lut.Build()
    return lut


def render(path, t, a):
    import numpy as np
    from vtkmodules.vtkRenderingAnnotation import vtkScalarBarActor
    from vtkmodules.vtkRenderingCore import vtkRenderer, vtkRenderWindow, vtkTextActor, vtkWindowToImageFilter
    from vtkmodules.vtkIOImage import vtkPNGWriter
    import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (the OpenGL back end registers itself)
    import vtkmodules.vtkRenderingFreeType  # noqa: F401  (text)
    continuum, interface = read_blocks(path)
    on_interface = a.field in INTERFACE_FIELDS
    if on_interface and interface is None:
        raise ToolError('%s: no interface elements to show %s' % (path, a.field))
    if not on_interface and continuum is None:
        raise ToolError('%s: no continuum elements to show %s (try --field opening or damage)' % (path, a.field))
    w, h = (int(v) for v in a.size.lower().split('x'))
    ren = vtkRenderer()
    ren.SetBackground(1.0, 1.0, 1.0)
    ncells = sum(g.GetNumberOfCells() for g in (continuum, interface) if g is not None)
    edges = a.edges == 'on' or (a.edges == 'auto' and ncells < 20000)
    assoc, values, label = field_values(interface if on_interface else continuum, a.field, a.cells)
    # the range over the points of the cells drawn (every frame lists every node; a node of no continuum element
    # holds 0 in the nodal averages) or over the cells
    shown = values
    if assoc == 'point':
        from vtkmodules.util.numpy_support import vtk_to_numpy
        grid = interface if on_interface else continuum
        used = np.unique(vtk_to_numpy(grid.GetCells().GetConnectivityArray()))
        shown = values[used]
    finite = shown[np.isfinite(shown)]
    data_rng = (float(finite.min()), float(finite.max())) if finite.size else (0.0, 0.0)
    rng = data_rng
    big = max(abs(rng[0]), abs(rng[1]), 1e-30)
    if rng[1] - rng[0] <= 1e-6 * big:
        # a field constant to round-off: one colour (the middle of a scale of +-0.1 %), not its round-off spread
        mid = 0.5 * (rng[0] + rng[1])
        rng = (mid - 1e-3 * big, mid + 1e-3 * big)
    coloured = None
    if continuum is not None:
        cont = deformed(continuum, a.scale)
        act = actor_of(cont, None if on_interface else assoc, None if on_interface else values, rng, edges=edges)
        if on_interface and not plane_model(continuum):
            act.GetProperty().SetOpacity(0.3)   # the interface seen through the bodies
        coloured = coloured or (None if on_interface else act)
        ren.AddActor(act)
    if interface is not None and a.interface != 'hide':
        data = interface_geometry(interface, a.interface, on_interface, a.scale)
        if on_interface:
            act = actor_of(data, 'cell', values, rng, edges=False, width=4.0)
            coloured = act
        else:
            act = actor_of(data, color=(0.2, 0.2, 0.2), width=2.0)
        ren.AddActor(act)
    if coloured is None:
        raise ToolError('%s: nothing to draw in colour (--interface hide with an interface field?)' % path)
    bar = vtkScalarBarActor()
    bar.SetLookupTable(coloured.GetMapper().GetLookupTable())
    bar.SetTitle(label.split(' (')[0].split(',')[0].replace(' averaged at the nodes', '').replace(
        'Mises of S', 'Mises') + ('' if '(' not in label else ' (' + label.rsplit('(', 1)[1]))
    bar.SetNumberOfLabels(7)
    bar.SetLabelFormat('%-#8.4g')
    bar.UnconstrainedFontSizeOn()
    for tp in (bar.GetTitleTextProperty(), bar.GetLabelTextProperty()):
        tp.SetColor(0, 0, 0)
        tp.ItalicOff()
        tp.BoldOff()
        tp.ShadowOff()
        tp.SetFontSize(15)
    bar.SetPosition(0.87, 0.08)
    bar.SetWidth(0.12)
    bar.SetHeight(0.8)
    # the white page with the bar and the title underneath (layer 0), the model on top in its viewport (layer 1)
    overlay = vtkRenderer()
    overlay.SetLayer(0)
    overlay.SetBackground(1.0, 1.0, 1.0)
    overlay.InteractiveOff()
    ren.SetLayer(1)
    overlay.AddActor2D(bar)
    title = vtkTextActor()
    title.SetInput('%s%s   %s: %.4g .. %.4g   displacement x %g' % (
        os.path.basename(path), '' if t is None else '   t = %g' % t, label, data_rng[0], data_rng[1], a.scale))
    title.GetTextProperty().SetColor(0, 0, 0)
    title.GetTextProperty().SetFontSize(16)
    title.SetPosition(10, h - 28)
    overlay.AddActor2D(title)
    ren.SetViewport(0.0, 0.0, 0.84, 0.94)
    set_camera(ren, continuum if continuum is not None else interface, a.view)
    win = vtkRenderWindow()
    win.SetOffScreenRendering(1)
    win.SetNumberOfLayers(2)
    win.AddRenderer(overlay)
    win.AddRenderer(ren)
    win.SetSize(w, h)
    win.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(win)
    grab.ReadFrontBufferOff()
    grab.Update()
    png = vtkPNGWriter()
    png.SetFileName(a.output)
    png.SetInputConnection(grab.GetOutputPort())
    png.Write()
    return data_rng


def plane_model(grid):
    """A plane model: z = 0 at every point."""
    b = grid.GetBounds()
    return abs(b[5] - b[4]) <= 1e-12 * max(abs(b[1] - b[0]), abs(b[3] - b[2]), 1e-30)


def set_camera(ren, grid, view):
    b = grid.GetBounds()
    plane = plane_model(grid)
    if view == 'auto':
        view = 'xy' if plane else 'iso'
    cam = ren.GetActiveCamera()
    c = [(b[0] + b[1]) / 2, (b[2] + b[3]) / 2, (b[4] + b[5]) / 2]
    d = {'xy': (0, 0, 1), 'xz': (0, -1, 0), 'yz': (1, 0, 0), 'iso': (1, -1, 0.8)}[view]
    up = {'xy': (0, 1, 0), 'xz': (0, 0, 1), 'yz': (0, 0, 1), 'iso': (0, 0, 1)}[view]
    cam.SetFocalPoint(*c)
    cam.SetPosition(*[c[k] + d[k] for k in range(3)])
    cam.SetViewUp(*up)
    ren.ResetCamera()


def ensure_display(argv):
    """Debian's VTK renders off-screen through an X server and aborts without one (exit 134): without $DISPLAY
    start again under xvfb-run, or say what to install."""
    if os.environ.get('DISPLAY'):
        return
    if os.environ.get('LDFCZ_UNDER_XVFB') == '1':
        raise ToolError('xvfb-run gave no X display')
    xvfb = shutil.which('xvfb-run')
    if xvfb is None:
        raise ToolError('VTK (Debian\'s python3-vtk9) renders through an X server and there is none ($DISPLAY is '
                        'empty): install xvfb and xauth (apt-get install xvfb xauth; tools/setup.sh does), or run '
                        'under an X session')
    os.environ['LDFCZ_UNDER_XVFB'] = '1'
    reexec([xvfb, '-a', '-s', '-screen 0 1600x1200x24', sys.executable])


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    a = parse(argv)
    try:
        w, h = (int(v) for v in a.size.lower().split('x'))
        if w < 64 or h < 64 or w > 8000 or h > 8000:
            raise ValueError
    except ValueError:
        raise ToolError('--size %s: WxH in pixels expected, 64 to 8000 each (e.g. 1200x800)' % a.size) from None
    if not (math.isfinite(a.scale)):
        raise ToolError('--scale must be a finite number')
    path, t = frame_file(a.run, a.frame, a.time)
    if not a.output:
        a.output = os.path.splitext(path)[0] + '_%s.png' % a.field
    if os.path.isdir(a.output):
        raise ToolError('%s: is a directory (-o names the PNG file)' % a.output)
    # check the frame and the field before an X server is started
    continuum, interface = read_blocks(path)
    field_values(interface if a.field in INTERFACE_FIELDS else continuum or interface, a.field, a.cells)
    ensure_display(argv)
    rng = render(path, t, a)
    print('render_frame.py: wrote %s (%s of %s, range %.6g .. %.6g)' % (a.output, a.field, path, rng[0], rng[1]))
    return 0


if __name__ == '__main__':
    from ldfcz_tools.cli import run
    sys.exit(run('render_frame'))
