// The ghost surfels of a distributed cloud: every rank holds a piece, and a surfel's B needs
// the sources within the kernel's reach of it, wherever they are. Each rank sends the others
// the points of its piece that lie within their reach (their bounds grown by it); it keeps
// what it receives after its own points, flagged DUPLICATEPOINT in VTK's ghost array, so that
// vtkSurfelMapper lights them and lets them scatter, but does not draw them.
#ifndef sssGhostSurfels_h
#define sssGhostSurfels_h

#include "vtkType.h"

#include <cstddef>

class vtkMultiProcessController;
class vtkPolyData;

namespace sss
{

struct GhostReport
{
  vtkIdType own = 0;       // points of this rank's piece
  vtkIdType received = 0;  // ghosts from the other ranks
  vtkIdType sent = 0;      // points sent, summed over the other ranks
  std::size_t bytes_sent = 0;
};

// `piece`: points with 3-component point normals (any other point data is left behind).
// `reach`: scene units. Collective: every rank of `controller` must call it, also with an
// empty piece. A null controller or a single rank gives `piece` itself with no ghosts.
GhostReport add_ghost_surfels(
  vtkMultiProcessController* controller, vtkPolyData* piece, double reach, vtkPolyData* out);

}

#endif
