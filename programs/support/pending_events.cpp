#include "pending_events.h"

#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"

#include <X11/Xlib.h>

namespace sss::cli {

void process_pending_events(vtkRenderWindowInteractor* interactor) {
  if (!interactor || !interactor->GetRenderWindow()) return;
  auto* display = static_cast<Display*>(interactor->GetRenderWindow()->GetGenericDisplayId());
  if (display && XPending(display) > 0) interactor->ProcessEvents();
}

}  // namespace sss::cli
