// The light maps of step 1, one atlas for every light (with the paper's pyramid above each
// map): where each light's levels lie in the atlas, how a map lies in the local frame, and
// the lights.

uniform int lightCount;
uniform int levelCount[SSS_MAX_LIGHTS];
uniform vec4 levelRect[SSS_MAX_LIGHTS * SSS_MAX_LEVELS];  // atlas origin xy, size zw
uniform float texelSize[SSS_MAX_LIGHTS];                   // level 0 texel edge, mm
uniform vec3 mapAxisU[SSS_MAX_LIGHTS];    // the map's image axes in the local frame
uniform vec3 mapAxisV[SSS_MAX_LIGHTS];
uniform vec2 mapCorner[SSS_MAX_LIGHTS];   // plane coordinates of the map's lower-left corner
uniform vec3 lightDirection[SSS_MAX_LIGHTS];   // towards each light, local frame
uniform vec3 lightIrradiance[SSS_MAX_LIGHTS];  // per channel
