# fbmRender.py: headless snapshots of an fbmFoam case with ParaView.
#
#   xvfb-run -a pvbatch bin/fbmRender.py CASE [-o DIR] [--field U|p|alpha.solid]
#                                          [--at t1,t2,...] [--size WxH]
#
# Opens CASE/case.foam (created if missing) with ParaView's OpenFOAM reader,
# colours the internal mesh by the field (magnitude for vectors), outlines
# the bodies with the alpha.solid = 0.5 contour, draws the lagrangian cloud
# fbmBodies as points, and writes DIR/<case>_<time>.png for each time.
import argparse
import os
import sys

from paraview.simple import (
    OpenFOAMReader, Contour, Show, Hide, Render, SaveScreenshot,
    GetActiveViewOrCreate, ColorBy, GetColorTransferFunction,
    GetAnimationScene, ExtractBlock, MergeBlocks)

parser = argparse.ArgumentParser()
parser.add_argument('case')
parser.add_argument('-o', '--output', default=None)
parser.add_argument('--field', default='U')
parser.add_argument('--at', dest='times', default=None)
parser.add_argument('--size', default='800x800')
args = parser.parse_args(sys.argv[1:])

case = os.path.abspath(args.case)
out = os.path.abspath(args.output or case)
os.makedirs(out, exist_ok=True)
foam = os.path.join(case, 'case.foam')
if not os.path.exists(foam):
    open(foam, 'w').close()

reader = OpenFOAMReader(FileName=foam)
reader.MeshRegions = ['internalMesh', 'lagrangian/fbmBodies']
reader.UpdatePipelineInformation()
times = list(reader.TimestepValues) if reader.TimestepValues else [0.0]
if args.times:
    wanted = [float(t) for t in args.times.split(',')]
    times = [min(times, key=lambda t: abs(t - w)) for w in wanted]

view = GetActiveViewOrCreate('RenderView')
w, h = (int(x) for x in args.size.split('x'))
view.ViewSize = [w, h]
view.OrientationAxesVisibility = 0

mesh = MergeBlocks(Input=ExtractBlock(Input=reader, Selectors=['/Root/internalMesh']))
meshDisplay = Show(mesh, view)
ColorBy(meshDisplay, ('CELLS', args.field, 'Magnitude'))
meshDisplay.SetScalarBarVisibility(view, True)

surface = Contour(Input=mesh, ContourBy=['POINTS', 'alpha.solid'],
                  Isosurfaces=[0.5])
surfaceDisplay = Show(surface, view)
surfaceDisplay.DiffuseColor = [1, 1, 1]
surfaceDisplay.LineWidth = 2

cloud = MergeBlocks(Input=ExtractBlock(Input=reader,
                                       Selectors=['/Root/lagrangian/fbmBodies']))
cloudDisplay = Show(cloud, view)
cloudDisplay.SetRepresentationType('Points')
cloudDisplay.PointSize = 6
cloudDisplay.DiffuseColor = [0, 0, 0]
cloudDisplay.AmbientColor = [0, 0, 0]

view.InteractionMode = '2D'
scene = GetAnimationScene()
name = os.path.basename(case.rstrip('/'))
for t in times:
    view.ViewTime = t
    mesh.UpdatePipeline(t)
    GetColorTransferFunction(args.field).RescaleTransferFunction(0.0, 1.0)
    meshDisplay.RescaleTransferFunctionToDataRange(False, True)
    view.ResetCamera()
    view.CameraParallelProjection = 1
    view.ResetCamera()
    Render(view)
    png = os.path.join(out, '%s_%g.png' % (name, t))
    SaveScreenshot(png, view, ImageResolution=[w, h])
    print('wrote', png)
