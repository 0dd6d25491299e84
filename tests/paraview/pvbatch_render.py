"""Renders a point cloud with normals as Translucent Surfels in a Translucent Render View, under
pvbatch (one rank or `mpirun -np N pvbatch`), with the camera, light and tone mapping that
sss_render uses, so that the two images can be compared.

  pvbatch pvbatch_render.py PLUGIN CLOUD OUT.png [--material M] [--mm-per-unit MM] [--size WxH]
      [--view-dir X,Y,Z] [--up X,Y,Z] [--light-dir X,Y,Z] [--split N] [--layout]

or in ParaView's GUI (scripts/pvbatch.sh --gui), which hands a script no arguments: then they
come from SSS_SCRIPT_ARGS (JSON), or as the Python client of a pvserver (scripts/pvbatch.sh
--client-server N passes --url cs://HOST:PORT): the plugin is loaded on both sides. --layout puts the view in the GUI's layout and draws it there
first, then sets the layout to the image's size (ParaView's preview mode), as a user who opens
the view and then resizes it.

CLOUD is a .ply or .vtp of points with normals. --split N cuts it along x into N pieces of
equal counts, --cuts X1,X2,... at those x (a .pvtp beside OUT); ParaView's reader hands the
pieces out one per rank. With -v=INFO each rank logs its surfels, the ghosts it received and
the bytes it sent.
"""
import argparse
import json
import os
import sys

from paraview.simple import *  # noqa: F401,F403
from paraview import servermanager as sm


def vector(text):
    return [float(v) for v in text.split(",")]


def split_along_x(cloud_path, pieces, cuts, stem):
    """Writes the .vtp files of the cloud cut along x (into `pieces` of equal counts, or at
    the x of `cuts`), and the .pvtp naming them."""
    from paraview.vtk.util.numpy_support import numpy_to_vtk, vtk_to_numpy
    from vtkmodules.vtkCommonCore import vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkPolyData
    from vtkmodules.vtkIOPLY import vtkPLYReader
    from vtkmodules.vtkIOXML import vtkXMLPolyDataReader, vtkXMLPolyDataWriter
    import numpy

    reader = vtkPLYReader() if cloud_path.endswith(".ply") else vtkXMLPolyDataReader()
    reader.SetFileName(cloud_path)
    reader.Update()
    cloud = reader.GetOutput()
    xyz = vtk_to_numpy(cloud.GetPoints().GetData())
    normals = vtk_to_numpy(cloud.GetPointData().GetNormals())
    order = numpy.argsort(xyz[:, 0], kind="stable")
    if cuts:
        parts = numpy.split(order, numpy.searchsorted(xyz[order, 0], cuts))
    else:
        parts = numpy.array_split(order, pieces)
    names = []
    for k, part in enumerate(parts):
        part = numpy.sort(part)
        piece = vtkPolyData()
        points = vtkPoints()
        points.SetData(numpy_to_vtk(numpy.ascontiguousarray(xyz[part]), deep=True))
        piece.SetPoints(points)
        n = numpy_to_vtk(numpy.ascontiguousarray(normals[part]), deep=True)
        n.SetName("Normals")
        piece.GetPointData().SetNormals(n)
        name = "%s_%d.vtp" % (os.path.basename(stem), k)
        writer = vtkXMLPolyDataWriter()
        writer.SetFileName(os.path.join(os.path.dirname(stem), name))
        writer.SetInputData(piece)
        writer.Write()
        names.append(name)
    with open(stem + ".pvtp", "w") as f:
        f.write('<?xml version="1.0"?>\n<VTKFile type="PPolyData" version="0.1">\n'
                '<PPolyData GhostLevel="0">\n<PPoints><PDataArray type="Float32" '
                'NumberOfComponents="3"/></PPoints>\n<PPointData Normals="Normals">'
                '<PDataArray type="Float32" Name="Normals" NumberOfComponents="3"/>'
                '</PPointData>\n')
        for name in names:
            f.write('<Piece Source="%s"/>\n' % name)
        f.write("</PPolyData>\n</VTKFile>\n")
    return stem + ".pvtp"


def main():
    p = argparse.ArgumentParser()
    p.add_argument("plugin")
    p.add_argument("cloud")
    p.add_argument("output")
    p.add_argument("--material", default="marble")
    p.add_argument("--mm-per-unit", type=float, default=1.0)
    p.add_argument("--size", default="400x400")
    p.add_argument("--view-dir", default="0,-1,0.6")
    p.add_argument("--up", default="0,0,1")
    p.add_argument("--light-dir", default="-0.3,0.5,0.8")
    p.add_argument("--split", type=int, default=0)
    p.add_argument("--cuts", default="")
    p.add_argument("--layout", action="store_true")
    p.add_argument("--url", default="")
    given = os.environ.get("SSS_SCRIPT_ARGS")
    a = p.parse_args(json.loads(given) if given is not None else sys.argv[1:])

    if a.url:
        host, port = a.url.split("://", 1)[-1].rsplit(":", 1)
        Connect(host, int(port))
        LoadPlugin(a.plugin, remote=False, ns=globals())  # the client's proxies of the view
    LoadPlugin(a.plugin, ns=globals())
    pm = sm.vtkProcessModule.GetProcessModule()
    cloud = a.cloud
    if a.split > 0 or a.cuts:
        stem = os.path.splitext(a.output)[0] + "_pieces"
        # One rank writes the pieces; all read them (a .pvtp is read in parallel).
        if pm.GetPartitionId() == 0:
            split_along_x(a.cloud, a.split, vector(a.cuts) if a.cuts else [], stem)
        cloud = stem + ".pvtp"
    source = OpenDataFile(cloud)

    view = CreateView("TranslucentRenderView")
    width, height = (int(v) for v in a.size.split("x"))
    view.ViewSize = [width, height]
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = [0, 0, 0]
    view.UseLight = 0  # no light kit: the one light below, as sss_render's
    view.SubsurfaceExposure = 1.0
    light = AddLight(view=view)
    light.Coords = "Scene"
    light.Type = "Directional"
    light.Position = vector(a.light_dir)
    light.FocalPoint = [0, 0, 0]
    light.Intensity = 1.0

    display = Show(source, view)
    display.SetRepresentationType("Translucent Surfels")
    display.TranslucentMaterial = a.material
    display.MillimetresPerUnit = a.mm_per_unit
    if a.layout:
        layout = GetLayout() or CreateLayout()
        AssignViewToLayout(view=view, layout=layout, hint=0)
        Render(view)  # at the layout's size
        layout.PreviewMode = [width, height]
    # sss_render's camera: looking at the bounds' centre along -view_dir, then fitted.
    source.UpdatePipeline()
    b = source.GetDataInformation().GetBounds()
    centre = [(b[0] + b[1]) / 2, (b[2] + b[3]) / 2, (b[4] + b[5]) / 2]
    d = vector(a.view_dir)
    norm = sum(v * v for v in d) ** 0.5
    view.CameraFocalPoint = centre
    view.CameraPosition = [centre[i] + d[i] / norm for i in range(3)]
    view.CameraViewUp = vector(a.up)
    view.CameraViewAngle = 30
    view.ResetCamera()
    Render(view)
    SaveScreenshot(a.output, view, ImageResolution=[width, height])


if __name__ == "__main__":
    main()
