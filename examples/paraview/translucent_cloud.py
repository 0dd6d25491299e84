"""A point cloud as translucent surfels in ParaView, on one rank or many:

  bash scripts/pvbatch.sh [-np N] examples/paraview/translucent_cloud.py CLOUD OUT.png
      [MATERIAL] [MM_PER_UNIT]

CLOUD: any file ParaView reads (.ply, .vtp, .pcd through its PDAL or PCL readers where built);
points need normals, a mesh gets them from its faces. On N ranks the cloud is split with
Redistribute DataSet, and each rank receives the surfels of the others within the kernel's
reach as ghosts. The plugin is SSS_PARAVIEW_PLUGIN (scripts/pvbatch.sh sets it) or the
TranslucentPointClouds.so found through PV_PLUGIN_PATH.
"""
import os
import sys

from paraview.simple import *  # noqa: F401,F403

cloud_path, output = sys.argv[1], sys.argv[2]
material = sys.argv[3] if len(sys.argv) > 3 else "marble"
mm_per_unit = float(sys.argv[4]) if len(sys.argv) > 4 else 1000.0

LoadPlugin(os.environ.get("SSS_PARAVIEW_PLUGIN", "TranslucentPointClouds"), ns=globals())

source = OpenDataFile(cloud_path)
source.UpdatePipeline()
arrays = source.PointData.keys()
if "Normals" not in arrays and not ("nx" in arrays or "Normals_" in arrays):
    source = GenerateSurfaceNormals(Input=source, Splitting=0)  # a mesh: normals from faces
pieces = RedistributeDataSet(Input=source)  # one piece per rank

view = CreateView("TranslucentRenderView")
view.ViewSize = [800, 600]
view.OrientationAxesVisibility = 0
view.UseColorPaletteForBackground = 0
view.Background = [0.05, 0.05, 0.07]
view.UseLight = 0  # one light from the upper left instead of the light kit
light = AddLight(view=view)
light.Coords = "Camera"
light.Type = "Directional"
light.Position = [-1.0, 1.0, 1.0]
light.FocalPoint = [0.0, 0.0, 0.0]

display = Show(pieces, view)
display.SetRepresentationType("Translucent Surfels")
display.TranslucentMaterial = material
display.MillimetresPerUnit = mm_per_unit
view.ResetCamera()
Render(view)
SaveScreenshot(output, view)
print("wrote", output)
