#include "sssPclPendingEvents.h"

#include <vtkRenderWindow.h>
#include <vtkRenderWindowInteractor.h>

#include <X11/Xlib.h>

namespace sss {

void processPendingEvents(vtkRenderWindowInteractor* interactor) {
  if (!interactor || !interactor->GetRenderWindow()) return;
  auto* display = static_cast<Display*>(interactor->GetRenderWindow()->GetGenericDisplayId());
  if (display && XPending(display) > 0) interactor->ProcessEvents();
}

}  // namespace sss
