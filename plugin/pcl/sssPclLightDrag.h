// A light turned with the mouse in a PCLVisualizer window: Ctrl+Shift and a left-button drag
// (as MeshLab turns its light) reports the drag in degrees, and the camera stays where it is
// while it lasts; every other mouse action reaches PCL's interactor as before.
#pragma once

#include <pcl/visualization/pcl_visualizer.h>
#include <vtkSmartPointer.h>

#include <functional>

class vtkCallbackCommand;
class vtkObject;

namespace sss {

class LightDrag {
 public:
  // Degrees to the right and up since the last call, for the drag's pointer motion.
  using Turn = std::function<void(double right_degrees, double up_degrees)>;
  static constexpr double kDegreesPerPixel = 0.5;

  // Listens to the viewer's interactor (which must exist: a viewer made with its interactor)
  // until destroyed.
  LightDrag(pcl::visualization::PCLVisualizer& viewer, Turn turn);
  ~LightDrag();
  LightDrag(const LightDrag&) = delete;
  LightDrag& operator=(const LightDrag&) = delete;

  bool dragging() const { return dragging_; }

 private:
  static void on_event(vtkObject* caller, unsigned long event, void* self, void*);

  vtkSmartPointer<vtkRenderWindowInteractor> interactor_;
  vtkSmartPointer<vtkCallbackCommand> command_;
  Turn turn_;
  bool dragging_ = false;
  int last_x_ = 0, last_y_ = 0;
};

}  // namespace sss
