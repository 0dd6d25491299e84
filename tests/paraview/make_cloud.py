"""Writes a cloud with normals as an ascii PLY of x y z nx ny nz:
  pvbatch make_cloud.py MESH.ply OUT.ply   the mesh's points with the normals of its faces
                                           (vtkPolyDataNormals, no splitting), less the points
                                           no face touches
  pvbatch make_cloud.py --shadow-scene OUT.ply
      in metres: a floor 1 m square at z = 0 (x from 0 to 1, 20 mm apart) and a ball of
      radius 0.15 m at (-0.3, 0.5, 0.4) (Fibonacci lattice, about 10 mm apart); a light from
      (-1, 0, 1) casts the ball's shadow onto the floor around x = 0.1, far beyond marble's reach
"""
import math
import sys

from vtkmodules.vtkFiltersCore import vtkPolyDataNormals
from vtkmodules.vtkIOPLY import vtkPLYReader
from paraview.vtk.util.numpy_support import vtk_to_numpy
import numpy



def mesh_points(path):
    reader = vtkPLYReader()
    reader.SetFileName(path)
    normals = vtkPolyDataNormals()
    normals.SetInputConnection(reader.GetOutputPort())
    normals.SplittingOff()
    normals.ComputePointNormalsOn()
    normals.Update()
    mesh = normals.GetOutput()
    xyz = vtk_to_numpy(mesh.GetPoints().GetData()).astype(float)
    n = vtk_to_numpy(mesh.GetPointData().GetNormals()).astype(float)
    return xyz, n


def shadow_scene():
    g = numpy.arange(0.0, 1.0 + 1e-9, 0.02)
    fx, fy = numpy.meshgrid(g, g)
    floor = numpy.stack([fx.ravel(), fy.ravel(), numpy.zeros(fx.size)], axis=1)
    count = 2800
    k = numpy.arange(count) + 0.5
    z = 1.0 - 2.0 * k / count
    phi = k * math.pi * (3.0 - math.sqrt(5.0))
    r = numpy.sqrt(1.0 - z * z)
    sphere = numpy.stack([r * numpy.cos(phi), r * numpy.sin(phi), z], axis=1)
    xyz = numpy.vstack([floor, 0.15 * sphere + [-0.3, 0.5, 0.4]])
    n = numpy.vstack([numpy.tile([0.0, 0.0, 1.0], (len(floor), 1)), sphere])
    return xyz, n


xyz, n = shadow_scene() if sys.argv[1] == "--shadow-scene" else mesh_points(sys.argv[1])
keep = numpy.linalg.norm(n, axis=1) > 0.5
with open(sys.argv[2], "w") as f:
    f.write("ply\nformat ascii 1.0\nelement vertex %d\n" % keep.sum())
    f.write("".join("property float %s\n" % c for c in ("x", "y", "z", "nx", "ny", "nz")))
    f.write("end_header\n")
    numpy.savetxt(f, numpy.hstack([xyz[keep], n[keep]]), fmt="%.7g")
