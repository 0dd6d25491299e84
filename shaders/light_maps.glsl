// The illumination maps of step 1 (illumination_fs.glsl) and their pyramids, one atlas for
// every light: the samplers and where each light's levels lie in the atlas.

uniform sampler2D mapPoint;        // xyz: point (local mm), w: summed power over its channels
uniform sampler2D mapPower;        // rgb: E dA, w: lit texels
uniform sampler2D mapNormal;       // xyz: unit normal towards the light, w: spread along it
uniform sampler2D mapCovariance0;  // xx, yy, zz, xy of the points (mm^2)
uniform sampler2D mapCovariance1;  // xz, yz
uniform int lightCount;
uniform int levelCount[SSS_MAX_LIGHTS];
uniform vec4 levelRect[SSS_MAX_LIGHTS * SSS_MAX_LEVELS];  // atlas origin xy, size zw
uniform float texelSize[SSS_MAX_LIGHTS];                   // level 0 texel edge, mm
uniform vec3 mapAxisU[SSS_MAX_LIGHTS];    // the map's image axes in the local frame
uniform vec3 mapAxisV[SSS_MAX_LIGHTS];
uniform vec2 mapCorner[SSS_MAX_LIGHTS];   // plane coordinates of the map's lower-left corner
