//VTK::System::Dec
// Step 2: one GL point per refined cell (refined_cells_fs.glsl), drawn at the cell's texel of E
// (the surfel list's layout); vertex i reads the refined block's cell i, sixteen to a 4 x 4
// square, the squares row by row (sssLitCells.cxx).

in vec2 cellTexel;     // the cell's texel in the surfel list
uniform vec2 listSize;
uniform int refinedWidth;  // of the refined block, a multiple of 4

flat out ivec2 cell;
flat out ivec2 refined;

void main()
{
  cell = ivec2(cellTexel);
  int square = gl_VertexID / 16;
  int within = gl_VertexID % 16;
  int squaresPerRow = refinedWidth / 4;
  refined = ivec2(4 * (square % squaresPerRow) + within % 4, 4 * (square / squaresPerRow) + within / 4);
  gl_Position = vec4((cellTexel + 0.5) / listSize * 2.0 - 1.0, 0.0, 1.0);
  gl_PointSize = 1.0;
}
