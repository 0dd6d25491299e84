"""Writes the points of a mesh with the normals of its faces (vtkPolyDataNormals, no splitting)
as an ascii PLY of x y z nx ny nz, leaving out points that no face touches:
  pvbatch make_cloud.py MESH.ply OUT.ply
"""
import sys

from vtkmodules.vtkFiltersCore import vtkPolyDataNormals
from vtkmodules.vtkIOPLY import vtkPLYReader
from paraview.vtk.util.numpy_support import vtk_to_numpy
import numpy

reader = vtkPLYReader()
reader.SetFileName(sys.argv[1])
normals = vtkPolyDataNormals()
normals.SetInputConnection(reader.GetOutputPort())
normals.SplittingOff()
normals.ComputePointNormalsOn()
normals.Update()
mesh = normals.GetOutput()
xyz = vtk_to_numpy(mesh.GetPoints().GetData()).astype(float)
n = vtk_to_numpy(mesh.GetPointData().GetNormals()).astype(float)
keep = numpy.linalg.norm(n, axis=1) > 0.5
with open(sys.argv[2], "w") as f:
    f.write("ply\nformat ascii 1.0\nelement vertex %d\n" % keep.sum())
    f.write("".join("property float %s\n" % c for c in ("x", "y", "z", "nx", "ny", "nz")))
    f.write("end_header\n")
    numpy.savetxt(f, numpy.hstack([xyz[keep], n[keep]]), fmt="%.7g")
