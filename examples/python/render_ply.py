#!/usr/bin/python3
"""Renders a PLY file as a translucent surfel cloud to a PNG, offscreen (EGL, no display).

Every point becomes a surfel; its normal comes from the file (nx, ny, nz) or, for a mesh
without normals, from vtkPolyDataNormals. The project's Python package must be importable
(see the README), for example:

  PYTHONPATH=build/lib/python3/dist-packages examples/python/render_ply.py bunny.ply \\
      --material marble --mm-per-unit 1000 --output bunny.png
"""
import argparse
import os
import re
import subprocess
import sys

import numpy
from vtkmodules.vtkFiltersCore import vtkPolyDataNormals
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkIOPLY import vtkPLYReader
from vtkmodules.vtkRenderingCore import (vtkActor, vtkLight, vtkRenderer,
                                         vtkWindowToImageFilter)

try:
    from sss import (vtkEGLSurfacelessRenderWindow, vtkSubsurfacePass, vtkSurfelMapper,
                     vtkTranslucentMaterial)
except ImportError as error:
    sys.exit(f"render_ply.py: {error}: put the build's or the install's "
             "lib/python3/dist-packages on PYTHONPATH (see the README)")


class RenderError(Exception):
    """A problem with the input or the rendering, told to the user in one line."""


def parse_size(text):
    """'512' or '640x480' -> (width, height)."""
    parts = text.lower().split("x")
    try:
        width, height = (int(parts[0]), int(parts[0])) if len(parts) == 1 else map(int, parts)
    except ValueError:
        raise argparse.ArgumentTypeError(f"'{text}' is not N or WxH")
    if not (1 <= width <= 16384 and 1 <= height <= 16384):
        raise argparse.ArgumentTypeError(f"'{text}': sides must be 1 to 16384 pixels")
    return width, height


def parse_arguments():
    parser = argparse.ArgumentParser(
        description="Render a PLY point cloud or mesh as a translucent material to a PNG.")
    parser.add_argument("ply", help="input .ply with points (and normals or faces)")
    parser.add_argument("--material", default="marble",
                        help="measured preset: apple, chicken1, chicken2, cream, ketchup, "
                             "marble, potato, skimmilk, skin1, skin2, spectralon, wholemilk "
                             "(default marble)")
    parser.add_argument("--mm-per-unit", type=float, default=1.0,
                        help="millimetres per scene unit, 1000 for a scan in metres (default 1)")
    parser.add_argument("--output", help="PNG to write (default: the input's name with .png, "
                                         "in the current folder)")
    parser.add_argument("--size", type=parse_size, default=(512, 512),
                        help="image size, N or WxH pixels (default 512)")
    parser.add_argument("--radius-scale", type=float, default=1.0,
                        help="multiplies the disc radius that closes the surface, which the "
                             "mapper measures (default 1)")
    args = parser.parse_args()
    if not args.mm_per_unit > 0:
        parser.error("--mm-per-unit must be positive")
    if not args.radius_scale > 0:
        parser.error("--radius-scale must be positive")
    if args.output is None:
        args.output = os.path.splitext(os.path.basename(args.ply))[0] + ".png"
    return args


def check_ply_reads_cleanly(path):
    """Reads the file once in a child process: VTK 9.1's vtkPLYReader crashes on some truncated
    binary files and only prints a message for truncated ASCII ones."""
    read = ("import sys\nfrom vtkmodules.vtkIOPLY import vtkPLYReader\n"
            "reader = vtkPLYReader()\nreader.SetFileName(sys.argv[1])\nreader.Update()")
    child = subprocess.run([sys.executable, "-c", read, path], capture_output=True, text=True)
    said = re.sub(r"\x1b\[[0-9;]*m", "", child.stderr).strip().splitlines()
    if child.returncode != 0:
        raise RenderError(f"{path}: truncated or malformed (VTK's PLY reader crashed on it)")
    if said:
        raise RenderError(f"{path}: truncated or malformed (VTK's PLY reader: {said[-1]})")


def read_surfels(path):
    """The PLY's points with point normals, computed from its faces when it has none."""
    if not os.path.isfile(path):
        raise RenderError(f"{path}: no such file")
    if not os.access(path, os.R_OK):
        raise RenderError(f"{path}: not readable (permissions)")
    reader = vtkPLYReader()
    if not reader.CanReadFile(path):
        raise RenderError(f"{path}: not a PLY file")
    check_ply_reads_cleanly(path)
    reader.SetFileName(path)
    reader.Update()
    cloud = reader.GetOutput()
    if cloud.GetNumberOfPoints() == 0:
        raise RenderError(f"{path}: no points could be read")
    if cloud.GetPointData().GetNormals() is not None:
        return cloud
    if cloud.GetNumberOfPolys() == 0:
        raise RenderError(f"{path}: the points have no normals (nx, ny, nz) and there are no "
                          "faces to compute them from; estimate normals first (PCL, sss_render)")
    normals = vtkPolyDataNormals()
    normals.SetInputData(cloud)
    normals.ComputePointNormalsOn()
    normals.ComputeCellNormalsOff()
    normals.SplittingOff()  # one normal per point: splitting would duplicate surfels
    normals.ConsistencyOn()
    normals.Update()
    print(f"{path}: no normals in the file, computed them from its {cloud.GetNumberOfPolys()} "
          "faces", file=sys.stderr)
    return normals.GetOutput()


def light_from_above(renderer):
    """A directional light from above and slightly behind the object, as the camera sees it."""
    camera = renderer.GetActiveCamera()
    towards_camera = numpy.array(camera.GetPosition()) - numpy.array(camera.GetFocalPoint())
    towards_camera /= numpy.linalg.norm(towards_camera)
    up = numpy.array(camera.GetViewUp())
    right = numpy.cross(-towards_camera, up)
    light = vtkLight()
    light.SetLightTypeToSceneLight()
    light.SetPositional(False)
    light.SetFocalPoint(0, 0, 0)
    light.SetPosition(*(up - 0.3 * towards_camera - 0.4 * right))
    return light


def render(surfels, args):
    """The image (vtkImageData, RGB) of the surfels, translucent, lit from above."""
    material = vtkTranslucentMaterial()
    if not material.SetPreset(args.material):
        raise RenderError(f"unknown material '{args.material}'")
    material.SetMillimetresPerUnit(args.mm_per_unit)
    mapper = vtkSurfelMapper()
    mapper.SetInputData(surfels)
    mapper.SetRadiusScale(args.radius_scale)
    mapper.ScalarVisibilityOff()
    actor = vtkActor()
    actor.SetMapper(mapper)
    material.ApplyTo(actor)

    renderer = vtkRenderer()
    renderer.SetBackground(0, 0, 0)
    renderer.AddActor(actor)
    subsurface = vtkSubsurfacePass()
    subsurface.CaptureLinearImageOn()
    renderer.SetPass(subsurface)
    window = vtkEGLSurfacelessRenderWindow()
    window.SetSize(*args.size)
    window.AddRenderer(renderer)
    if not window.IsContextValid():
        raise RenderError(f"no EGL context: {window.GetLastError()}")

    renderer.ResetCamera()
    renderer.AutomaticLightCreationOff()
    renderer.AddLight(light_from_above(renderer))
    window.Render()
    if subsurface.GetLastTranslucentActors() != 1:
        problem = mapper.GetInputProblem() or "see the errors above"
        raise RenderError(f"{args.ply}: could not be rendered translucent ({problem})")
    white = subsurface.GetLinearImageQuantile(0.995)  # visible radiance shown white
    subsurface.SetExposure(1.0 / white if white > 0 else 1.0)
    renderer.GetActiveCamera().Modified()  # a camera-only change: the view step alone
    window.Render()

    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.SetInputBufferTypeToRGB()
    grab.ReadFrontBufferOff()
    grab.Update()
    print(f"{mapper.GetNumberOfSurfels()} surfels (radius {mapper.GetEffectiveRadius():g}), "
          f"{material.GetName()}, {args.mm_per_unit:g} mm per unit", file=sys.stderr)
    return grab.GetOutput()


def write_png(image, path):
    """Writes the whole file or nothing: a temporary file is renamed into place."""
    partial = path + ".partial"
    writer = vtkPNGWriter()
    writer.SetInputData(image)
    writer.SetFileName(partial)
    writer.Write()
    if writer.GetErrorCode() != 0 or not os.path.isfile(partial):
        if os.path.exists(partial):
            os.remove(partial)
        raise RenderError(f"{path}: could not be written")
    os.replace(partial, path)


def main():
    args = parse_arguments()
    try:
        write_png(render(read_surfels(args.ply), args), args.output)
    except RenderError as error:
        print(f"render_ply.py: {error}", file=sys.stderr)
        return 1
    print(f"wrote {args.output}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
