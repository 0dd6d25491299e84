// Step 3, injected into surfel_vs.glsl by the subsurface pass: the surfel's B, computed when
// light, geometry or material last changed, read by vertex id.
uniform sampler2D surfelRadiance;
uniform int surfelListWidth;
//SSS::Dipole::Dec
