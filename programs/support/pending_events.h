// The window's input without waiting for more, for a loop that has frames of its own to draw.
#ifndef SSS_PROGRAMS_PENDING_EVENTS_H
#define SSS_PROGRAMS_PENDING_EVENTS_H

class vtkRenderWindowInteractor;

namespace sss::cli {

// Dispatches the X events already queued for `interactor`'s window (keys, drags, exposes) and
// returns at once when there are none. PCLVisualizer::spinOnce and VTK 9.1's ProcessEvents wait
// up to a second for an event when none is queued, a second lost between a refinement's frames.
void process_pending_events(vtkRenderWindowInteractor* interactor);

}  // namespace sss::cli

#endif
