#include "sssPclPendingEvents.h"

#include <vtkRenderWindow.h>
#include <vtkRenderWindowInteractor.h>

#include <X11/Xlib.h>

namespace sss {

void processPendingEvents(vtkRenderWindowInteractor* interactor) {
  if (!interactor || !interactor->IsA("vtkXRenderWindowInteractor") ||
      !interactor->GetRenderWindow())
    return;  // no X window: nothing queued that this could see
  auto* display = static_cast<Display*>(interactor->GetRenderWindow()->GetGenericDisplayId());
  // ProcessEvents takes one event a call in VTK 9.1.
  while (display && XPending(display) > 0 && !interactor->GetDone()) interactor->ProcessEvents();
}

}  // namespace sss
