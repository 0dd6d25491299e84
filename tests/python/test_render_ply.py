"""examples/python/render_ply.py on procedural shapes written as PLY files in the build folder.

Run by CTest with the Python VTK belongs to; the environment names the example
(SSS_RENDER_PLY) and the folder to write in (SSS_TEST_OUTPUT_DIR), and PYTHONPATH reaches the
build tree's `sss` package.
"""
import os
import subprocess
import sys
import unittest

import numpy
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkIOImage import vtkPNGReader
from vtkmodules.vtkIOPLY import vtkPLYWriter

EXAMPLE = os.environ["SSS_RENDER_PLY"]
OUTPUT_DIR = os.environ["SSS_TEST_OUTPUT_DIR"]


def path_in_output(name):
    os.makedirs(OUTPUT_DIR, exist_ok=True)
    path = os.path.join(OUTPUT_DIR, name)
    if os.path.exists(path):
        os.remove(path)
    return path


def write_points_ply(path, points, normals=None):
    """A binary PLY of points (x, y, z) and, when given, normals (nx, ny, nz); no faces.

    vtkPLYWriter of VTK 9.1 leaves normals out, hence this writer."""
    columns = [points] if normals is None else [points, normals]
    names = "xyz" if normals is None else ["x", "y", "z", "nx", "ny", "nz"]
    header = ["ply", "format binary_little_endian 1.0", f"element vertex {len(points)}"]
    header += [f"property float {name}" for name in names]
    header += ["end_header", ""]
    with open(path, "wb") as out:
        out.write("\n".join(header).encode("ascii"))
        out.write(numpy.hstack(columns).astype("<f4").tobytes())


def sphere_samples(count, radius):
    """Points spread evenly over a sphere (a Fibonacci lattice) and their outward normals."""
    i = numpy.arange(count) + 0.5
    z = 1.0 - 2.0 * i / count
    ring = numpy.sqrt(1.0 - z * z)
    azimuth = numpy.pi * (3.0 - numpy.sqrt(5.0)) * i
    normals = numpy.stack([ring * numpy.cos(azimuth), ring * numpy.sin(azimuth), z], axis=1)
    return radius * normals, normals


def write_sphere_mesh_ply(path):
    """A vtkSphereSource mesh (binary PLY; vtkPLYWriter writes no normals)."""
    sphere = vtkSphereSource()
    sphere.SetRadius(0.5)
    sphere.SetThetaResolution(64)
    sphere.SetPhiResolution(64)
    writer = vtkPLYWriter()
    writer.SetInputConnection(sphere.GetOutputPort())
    writer.SetFileName(path)
    if writer.Write() != 1:
        raise OSError(f"{path}: could not be written")


def run_example(*arguments):
    return subprocess.run([sys.executable, EXAMPLE, *arguments], capture_output=True,
                          text=True, timeout=300)


def read_png(path):
    """(width, height, pixels as an array of shape (height * width, channels))."""
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    width, height, _ = image.GetDimensions()
    return width, height, vtk_to_numpy(image.GetPointData().GetScalars())


class RenderPly(unittest.TestCase):
    def assert_lit_png(self, result, png, width, height):
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertTrue(os.path.isfile(png), result.stderr)
        png_width, png_height, pixels = read_png(png)
        self.assertEqual((png_width, png_height), (width, height))
        brightness = pixels[:, :3].max(axis=1)
        lit = numpy.count_nonzero(brightness > 60)  # the example's background is black
        print(f"{png}: brightest {brightness.max()}, {lit} of {brightness.size} pixels lit")
        self.assertGreater(brightness.max(), 200, "the brightest pixel is tone mapped to white")
        self.assertGreater(lit, 0.05 * brightness.size, "a lit shape covers the image")

    def test_cloud_with_normals_renders_lit_png(self):
        ply = path_in_output("sphere_cloud.ply")
        write_points_ply(ply, *sphere_samples(6000, 0.5))
        png = path_in_output("sphere_cloud.png")
        result = run_example(ply, "--material", "marble", "--mm-per-unit", "30",
                             "--output", png, "--size", "160x120")
        self.assert_lit_png(result, png, 160, 120)

    def test_mesh_without_normals_gets_them_from_its_faces(self):
        ply = path_in_output("sphere_mesh.ply")
        write_sphere_mesh_ply(ply)
        png = path_in_output("sphere_mesh.png")
        result = run_example(ply, "--material", "skimmilk", "--mm-per-unit", "30",
                             "--output", png, "--size", "128")
        self.assertIn("computed them from its", result.stderr)
        self.assert_lit_png(result, png, 128, 128)

    def test_missing_file_fails_without_output(self):
        png = path_in_output("missing.png")
        result = run_example(os.path.join(OUTPUT_DIR, "no_such_cloud.ply"), "--output", png)
        self.assertNotEqual(result.returncode, 0)
        self.assertIn("no_such_cloud.ply: no such file", result.stderr)
        self.assertFalse(os.path.exists(png))

    def test_truncated_file_fails_clearly(self):
        ply = path_in_output("truncated.ply")
        write_sphere_mesh_ply(ply)
        os.truncate(ply, os.path.getsize(ply) * 3 // 5)
        png = path_in_output("truncated.png")
        result = run_example(ply, "--output", png)
        self.assertNotEqual(result.returncode, 0)
        self.assertIn("truncated.ply: truncated or malformed", result.stderr)
        self.assertFalse(os.path.exists(png))

    def test_points_without_normals_or_faces_fail_clearly(self):
        ply = path_in_output("bare_points.ply")
        write_points_ply(ply, sphere_samples(500, 0.5)[0])
        png = path_in_output("bare_points.png")
        result = run_example(ply, "--output", png)
        self.assertNotEqual(result.returncode, 0)
        self.assertIn("no normals", result.stderr)
        self.assertFalse(os.path.exists(png))


if __name__ == "__main__":
    unittest.main()
