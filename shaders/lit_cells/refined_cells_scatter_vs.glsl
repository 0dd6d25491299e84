//VTK::System::Dec
// Step 2: one GL point per refined cell (refined_cells_fs.glsl), drawn at the cell's texel of E
// (the surfel list's layout); vertex i reads texel i of the refined block.

in vec2 cellTexel;     // the cell's texel in the surfel list
uniform vec2 listSize;
uniform int refinedWidth;  // of the refined block

flat out ivec2 cell;
flat out ivec2 refined;

void main()
{
  cell = ivec2(cellTexel);
  refined = ivec2(gl_VertexID % refinedWidth, gl_VertexID / refinedWidth);
  gl_Position = vec4((cellTexel + 0.5) / listSize * 2.0 - 1.0, 0.0, 1.0);
  gl_PointSize = 1.0;
}
