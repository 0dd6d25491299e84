#include "sssPclLightDrag.h"

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkRenderWindowInteractor.h>

#include <stdexcept>

namespace sss {

namespace {
// Before the interactor style (its observers listen at priority 0), so that a drag it takes
// never reaches the camera.
constexpr float kBeforeTheStyle = 10.0f;
}  // namespace

LightDrag::LightDrag(pcl::visualization::PCLVisualizer& viewer, Turn turn)
    : interactor_(viewer.getRenderWindow()->GetInteractor()), turn_(std::move(turn)) {
  if (!interactor_) throw std::invalid_argument("the visualizer has no interactor to drag in");
  command_ = vtkSmartPointer<vtkCallbackCommand>::New();
  command_->SetCallback(on_event);
  command_->SetClientData(this);
  for (unsigned long event : {vtkCommand::LeftButtonPressEvent, vtkCommand::MouseMoveEvent,
                              vtkCommand::LeftButtonReleaseEvent})
    interactor_->AddObserver(event, command_, kBeforeTheStyle);
}

LightDrag::~LightDrag() { interactor_->RemoveObserver(command_); }

void LightDrag::on_event(vtkObject*, unsigned long event, void* data, void*) {
  auto& self = *static_cast<LightDrag*>(data);
  vtkRenderWindowInteractor& in = *self.interactor_;
  int x = 0, y = 0;
  in.GetEventPosition(x, y);
  if (event == vtkCommand::LeftButtonPressEvent) {
    self.dragging_ = in.GetControlKey() && in.GetShiftKey();  // a lost release ends here too
    if (!self.dragging_) return;
  } else if (!self.dragging_) {
    return;
  } else if (event == vtkCommand::MouseMoveEvent) {
    self.turn_(kDegreesPerPixel * (x - self.last_x_), kDegreesPerPixel * (y - self.last_y_));
  } else {
    self.dragging_ = false;
  }
  self.last_x_ = x;
  self.last_y_ = y;
  self.command_->SetAbortFlag(1);
}

}  // namespace sss
