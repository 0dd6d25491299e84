"""Converts sss_render's --bake PLY (double x y z, float nx ny nz, float red green blue) into a
.vtp of points with normals and double coordinates, which ParaView reads without rounding
georeferenced coordinates to floats as its PLY reader does, and with a vertex cell per point,
which Redistribute DataSet needs (it hands out cells; points without one are dropped):
  pvbatch examples/paraview/baked_to_vtp.py BAKED.ply OUT.vtp
"""
import sys

import numpy
from paraview.vtk.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter

with open(sys.argv[1], "rb") as f:
    header = b""
    while not header.endswith(b"end_header\n"):
        header += f.readline()
    count = int(header.split(b"element vertex ")[1].split(b"\n")[0])
    if b"property float nx" not in header:
        sys.exit("%s has no normals: bake it again with this sss_render" % sys.argv[1])
    layout = numpy.dtype([("xyz", "<f8", 3), ("n", "<f4", 3), ("rgb", "<f4", 3)])
    vertices = numpy.frombuffer(f.read(count * layout.itemsize), dtype=layout)
cloud = vtkPolyData()
points = vtkPoints()
points.SetData(numpy_to_vtk(numpy.ascontiguousarray(vertices["xyz"]), deep=True))
cloud.SetPoints(points)
vertices_cells = vtkCellArray()
vertices_cells.SetData(numpy_to_vtk(numpy.arange(count + 1, dtype=numpy.int64), deep=True),
                       numpy_to_vtk(numpy.arange(count, dtype=numpy.int64), deep=True))
cloud.SetVerts(vertices_cells)
normals = numpy_to_vtk(numpy.ascontiguousarray(vertices["n"]), deep=True)
normals.SetName("Normals")
cloud.GetPointData().SetNormals(normals)
writer = vtkXMLPolyDataWriter()
writer.SetFileName(sys.argv[2])
writer.SetInputData(cloud)
writer.SetDataModeToAppended()
writer.Write()
print("wrote %s: %d points" % (sys.argv[2], count))
