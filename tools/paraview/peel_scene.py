"""ParaView (pvpython, pvbatch or the GUI) set-up of a peel scene's frames (docs/scenes.md, docs/tools.md):

  pvbatch tools/paraview/peel_scene.py RUN/JOB.pvd [--png OUT.png] [--time T]
  pvpython tools/paraview/peel_scene.py RUN/JOB.pvd --state OUT.pvsm      (a state file to open in ParaView)
  LDFCZ_PVD=RUN/JOB.pvd paraview --script=tools/paraview/peel_scene.py      (the GUI, the same pipeline)

The pipeline: JOB.pvd read (ParaView reads ldfcz's multiblock frames directly), the continuum block warped by U and
coloured by the von Mises stress of S_nodal (the stress averaged at the nodes: smooth contours), the interface
block warped by U and filtered to the cells that still hold (damage < 0.99), drawn dark grey: the cells of a broken
interface, which span the gap between coating and substrate, are left out instead of covering the picture. The
view looks along -z for a plane model, at an angle for a 3D one; the last frame is shown (--time picks another).
Works with the frames of a distributed run (pieces) alike. Tested with Debian 12's ParaView 5.11 (pvbatch; its
python3-paraview conflicts with the python3-vtk9 the project's tools need: install it apart).
"""
import argparse
import os
import sys

from paraview import simple as pv


def mises_expression(name):
    s = name
    return ('sqrt(0.5*(({s}[:,0]-{s}[:,1])**2+({s}[:,1]-{s}[:,2])**2+({s}[:,2]-{s}[:,0])**2)'
            '+3*({s}[:,3]**2+{s}[:,4]**2+{s}[:,5]**2))').format(s=s)


def block(source, name):
    """The block NAME of the frames (ParaView 5.10+: selectors; older: its index)."""
    try:
        return pv.ExtractBlock(Input=source, Selectors=['/Root/' + name])
    except (AttributeError, TypeError):
        return pv.ExtractBlock(Input=source, BlockIndices=[1 if name == 'continuum' else 2])


def build(pvd, time=None):
    reader = pv.PVDReader(FileName=pvd)
    reader.UpdatePipelineInformation()
    times = list(reader.TimestepValues) if reader.TimestepValues else [0.0]
    t = times[-1] if time is None else min(times, key=lambda x: abs(x - time))
    view = pv.GetActiveViewOrCreate('RenderView')
    view.ViewSize = [1200, 800]
    view.ViewTime = t
    view.Background = [1.0, 1.0, 1.0]
    try:
        view.UseColorPaletteForBackground = 0
    except AttributeError:
        pass
    view.OrientationAxesVisibility = 0
    cont = pv.WarpByVector(Input=block(reader, 'continuum'), Vectors=['POINTS', 'U'])
    mises = pv.PythonCalculator(Input=cont, Expression=mises_expression('S_nodal'), ArrayName='Mises_nodal',
                                ArrayAssociation='Point Data')
    d = pv.Show(mises, view)
    d.Representation = 'Surface With Edges'
    d.EdgeColor = [0.2, 0.2, 0.2]
    pv.ColorBy(d, ('POINTS', 'Mises_nodal'))
    d.RescaleTransferFunctionToDataRange(True, False)
    d.SetScalarBarVisibility(view, True)
    lut = pv.GetColorTransferFunction('Mises_nodal')
    lut.ApplyPreset('Rainbow Uniform', True)
    bar = pv.GetScalarBar(lut, view)
    bar.Title = 'Mises (MPa)'
    bar.ComponentTitle = ''
    bar.TitleColor = bar.LabelColor = [0.0, 0.0, 0.0]
    bar.TitleFontSize, bar.LabelFontSize = 16, 14
    bar.WindowLocation = 'Any Location'
    bar.Position = [0.86, 0.1]
    bar.ScalarBarThickness = 16
    bar.HorizontalTitle = 1
    bar.ScalarBarLength = 0.8
    bar.RangeLabelFormat = '%-#6.3g'
    inter = pv.WarpByVector(Input=block(reader, 'interface'), Vectors=['POINTS', 'U'])
    holding = pv.Threshold(Input=inter, Scalars=['CELLS', 'damage'])
    try:
        holding.LowerThreshold, holding.UpperThreshold = 0.0, 0.99
    except AttributeError:
        holding.ThresholdRange = [0.0, 0.99]
    h = pv.Show(holding, view)
    h.ColorArrayName = ['POINTS', '']
    h.DiffuseColor = h.AmbientColor = [0.2, 0.2, 0.2]
    view.Update()
    # a plane model (z = 0 everywhere) is seen along -z
    b = reader.GetDataInformation().GetBounds()
    view.ResetCamera()
    cam = view.GetActiveCamera()
    if abs(b[5] - b[4]) <= 1e-12 * max(b[1] - b[0], b[3] - b[2], 1e-30):
        view.CameraPosition = [(b[0] + b[1]) / 2, (b[2] + b[3]) / 2, 1.0]
        view.CameraFocalPoint = [(b[0] + b[1]) / 2, (b[2] + b[3]) / 2, 0.0]
        view.CameraViewUp = [0.0, 1.0, 0.0]
    else:
        cam.Azimuth(-30)
        cam.Elevation(25)
    view.ResetCamera()
    return view, t


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('pvd', nargs='?', default=os.environ.get('LDFCZ_PVD', ''))
    ap.add_argument('--png', default='')
    ap.add_argument('--state', default='')
    ap.add_argument('--time', type=float, default=None)
    a = ap.parse_args()
    if not a.pvd or not os.path.isfile(a.pvd):
        sys.stderr.write('peel_scene.py: give a JOB.pvd (or set LDFCZ_PVD): %r is not a file\n' % a.pvd)
        return 2
    view, t = build(a.pvd, a.time)
    if a.png:
        pv.SaveScreenshot(a.png, view, ImageResolution=[1200, 800])
        print('peel_scene.py: wrote %s (frame at t = %g)' % (a.png, t))
    if a.state:
        pv.SaveState(a.state)
        print('peel_scene.py: wrote %s (open it in ParaView: File > Load State)' % a.state)
    if not a.png and not a.state:
        pv.Render(view)
    return 0


if __name__ == '__main__':
    rc = main()
    if rc:
        sys.exit(rc)
