// Step 2's far field on the GPU (far_field.glsl): at every surfel, a walk of each source
// pyramid (sssLitCells: the lit cells of all lights, one or two pyramids) over the cells beyond
// the near field's reach, a group of cells taken as one source once it is small and far enough
// (the opening angle), added to B.
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

// How far a far field drawn in parts has come: its quads (one per pyramid and walk root) drawn
// so far, of all, and of the next one the rows of the surfel list drawn so far; and how many
// rows a part draws (bands of a quad's receivers, each summing the same roots in the same
// order, so that B is the same as from whole quads).
struct FarFieldProgress
{
  int drawn = 0;
  int total = 0;
  int rows_drawn = 0;  // of quad `drawn`
  int band_rows = 0;   // 0: whole quads
  int narrowest_band = 0;  // the narrowest band_rows in this light move
  double band_seconds = 0.0;  // about what a band should take: a frame's time for the far field
  bool done() const { return drawn >= total; }
  // For a new light move: nothing drawn, the bands as wide as the last move's narrowest.
  void restart()
  {
    drawn = total = rows_drawn = 0;
    band_rows = narrowest_band;
    narrowest_band = 0;
  }
  // The share done, counting the rows of the quad under way (`rows`: the surfel list's).
  double share(int rows) const;
  // After a band that took `took` seconds: narrower in proportion when it took longer than
  // band_seconds, twice as wide (up to a few times this move's narrowest) when under a quarter.
  void fit_band(double took, int rows);
};

// The quads add_far_field draws.
int far_field_parts(const LitCells& cells);

// Adds the far field of the lit cells' pyramids into the bound target with `program` (a quad
// over the surfel list, `rows` high, that includes far_field.glsl), blending by addition: the quads
// from progress.drawn on (of the first, the rows from progress.rows_drawn on), all of them with
// infinite `seconds`; else in bands of rows, the first and then others only while fewer than
// that many seconds have passed (waiting for the GPU after each band to know), the rest left to
// a later call, the bands fitted to progress.band_seconds as they are timed (fit_band; a root's
// cells, and so the receivers that cost most, lie in a few rows).
void add_far_field(vtkOpenGLState* state, vtkOpenGLQuadHelper& quad, vtkShaderProgram* program,
  const LitCells& cells, int rows, const FarFieldSettings& settings,
  FarFieldProgress& progress, double seconds);
}

#endif
