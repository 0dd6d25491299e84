// Step 2's far field on the GPU (far_field.glsl): at every surfel, a walk of each light's
// source pyramid (sssLitCells) over the cells beyond the near field's reach, a group of cells
// taken as one source once it is small and far enough (the opening angle), added to B.
#ifndef sssFarField_h
#define sssFarField_h

class vtkOpenGLQuadHelper;
class vtkOpenGLState;
class vtkShaderProgram;

namespace sss
{

class LitCells;

// A channel bounds a group's radius in its diffusion lengths only while the group comes within
// the channel's support radius at this fraction of the kernel's integral: farther out the groups
// together carry less than it, so the opening angle alone bounds them. Measured on the Kinect
// table scene (marble, 1000 mm per unit): the far field's walk 9.97 s instead of 20.5 s with the
// bound out to the full support, the error against the reference 0.057 % mean (0.056 % before).
constexpr double kGroupSizeBoundFraction = 1e-3;

struct FarFieldSettings
{
  double opening_angle = 0;                // a group's spread over its distance
  double max_group_diffusion_lengths = 0;  // a group's radius, in 1/s_tr
  double support_radius = 0;               // mm: sources beyond add nothing
  double size_bound_reach[3] = {};  // mm per channel: its support at kGroupSizeBoundFraction
};

// How far a far field drawn in parts has come: its quads (one per light and walk root) drawn
// so far, of all.
struct FarFieldProgress
{
  int drawn = 0;
  int total = 0;
  bool done() const { return drawn >= total; }
};

// The quads add_far_field draws for `lights` lights.
int far_field_parts(const LitCells& cells, int lights);

// Adds the far field of `lights` lights into the bound target with `program` (a quad over the
// surfel list that includes far_field.glsl), blending by addition: the quads from
// progress.drawn on, all of them with infinite `seconds`, else the first and then others only
// while fewer than that many seconds have passed (waiting for the GPU after each quad to know),
// the rest left to a later call.
void add_far_field(vtkOpenGLState* state, vtkOpenGLQuadHelper& quad, vtkShaderProgram* program,
  const LitCells& cells, int lights, const FarFieldSettings& settings,
  FarFieldProgress& progress, double seconds);
}

#endif
