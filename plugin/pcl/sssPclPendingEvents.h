// A window's queued input without waiting for more, for a loop that has frames of its own to
// draw (a refinement's parts: TranslucentCloud::spinOnce).
#pragma once

class vtkRenderWindowInteractor;

namespace sss {

// Dispatches the X events already queued for `interactor`'s window (keys, drags, exposes) and
// returns at once when there are none, or when one of them ends the event loop (q, the window
// closed). Without an X interactor it does nothing. PCLVisualizer::spinOnce and VTK 9.1's ProcessEvents wait
// up to a second for an event when none is queued.
void processPendingEvents(vtkRenderWindowInteractor* interactor);

}  // namespace sss
