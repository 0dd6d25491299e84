// Surfel clouds the project makes itself: the demo shape and the shapes of the tests.
#pragma once

#include "surfel_cloud.h"

namespace sss {

// A square grid of the given spacing clipped to a disc of radius `disc_radius` in the plane
// z = 0, normals +z, disc radius 0.75 spacing (covers the plane). mm or any unit.
SurfelCloud make_slab(double disc_radius, double spacing);

// Points uniformly at random over the same disc (a Poisson sampling, as a mesh sampled at
// random), mean nearest-neighbour distance `spacing` (density 1 / (4 spacing^2)), normals +z,
// disc radius 1.5 spacings; `seed` picks the sampling.
SurfelCloud make_random_slab(double disc_radius, double spacing, unsigned seed);

// A torus around the z axis (ring radius R, tube radius r), sampled in rings about `spacing`
// apart so that the density is even, normals outward.
SurfelCloud make_torus(double R, double r, double spacing);

// `count` surfels along the x axis, `spacing` apart, normals +z, disc radius = spacing.
SurfelCloud make_line(int count, double spacing);

// A sphere of radius r in latitude rings about `spacing` apart, normals outward.
SurfelCloud make_sphere(double r, double spacing);

// `count` points on a sphere of radius r on a Fibonacci lattice (even density, no rings),
// normals outward, disc radius 1.5 mean nearest-neighbour spacings as the PCL glue takes it.
SurfelCloud make_fibonacci_sphere(double r, int count);

}  // namespace sss
