// The surfels of step 2 as one list texture in Hilbert order of position, laid out in 2-D Morton
// order too, so that every 2^k x 2^k square of texels holds surfels that lie close together
// (the far field's source pyramid reduces such squares) and the rasteriser's 4 x 4 blocks shade
// neighbours side by side. Texels past the last surfel are empty (thickness 0).

uniform sampler2D surfelPoint;   // xyz: local mm, w: surface thickness (mm), 0: empty texel
uniform sampler2D surfelShape;   // xyz: unit normal, w: mean curvature (1/mm)
uniform sampler2D surfelCell;    // x: cell radius (mm), y: cell area (mm^2), z: disc radius (mm),
                                 // w: noise height (mm, core/surfels/local_surface.h)
uniform sampler2D surfelAlbedo;  // rgb
