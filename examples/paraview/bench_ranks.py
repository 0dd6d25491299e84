"""Frame times of the Translucent Render View under pvbatch on the ranks it runs on:

  bash scripts/pvbatch.sh -np N -v=1 examples/paraview/bench_ranks.py CLOUD OUT.json
      [MATERIAL] [MM_PER_UNIT] [FRAMES]

CLOUD: a .vtp or .ply of points with normals (scripts/bench_paraview.sh makes them). The cloud
is split with Redistribute DataSet. Times: the first frame (ghost exchange, every step), then
FRAMES frames orbiting the camera (the view alone), then FRAMES frames moving the light (light
maps reduced over the ranks, steps 1-2, the view). With -v=1 each rank logs its ghosts and the
bytes it put into reductions each frame.
"""
import json
import sys
import time

from paraview.simple import *  # noqa: F401,F403
from paraview import servermanager as sm
import os

cloud_path, output = sys.argv[1], sys.argv[2]
material = sys.argv[3] if len(sys.argv) > 3 else "marble"
mm_per_unit = float(sys.argv[4]) if len(sys.argv) > 4 else 1.0
frames = int(sys.argv[5]) if len(sys.argv) > 5 else 5

LoadPlugin(os.environ["SSS_PARAVIEW_PLUGIN"], ns=globals())
ranks = sm.vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions()
pieces = RedistributeDataSet(Input=OpenDataFile(cloud_path))
view = CreateView("TranslucentRenderView")
view.ViewSize = [800, 600]
view.OrientationAxesVisibility = 0
view.UseLight = 0
light = AddLight(view=view)
light.Coords = "Scene"
light.Type = "Directional"
light.Position = [-0.3, 0.5, 0.8]
light.FocalPoint = [0, 0, 0]
display = Show(pieces, view)
display.SetRepresentationType("Translucent Surfels")
display.TranslucentMaterial = material
display.MillimetresPerUnit = mm_per_unit
view.ResetCamera()

start = time.perf_counter()
Render(view)
first = time.perf_counter() - start
camera = GetActiveCamera()
start = time.perf_counter()
for _ in range(frames):
    camera.Azimuth(360.0 / frames)
    Render(view)
camera_only = (time.perf_counter() - start) / frames
start = time.perf_counter()
for k in range(frames):
    light.Position = [-0.3 + 0.1 * (k + 1), 0.5, 0.8]
    Render(view)
light_moving = (time.perf_counter() - start) / frames
result = {"ranks": ranks, "cloud": os.path.basename(cloud_path), "material": material,
          "first_frame_s": first, "camera_only_s": camera_only, "light_moving_s": light_moving}
with open(output, "w") as f:
    json.dump(result, f, indent=1)
print(json.dumps(result))
