  // Step 3 (eq. 14, 16): Lo = Ft(eta, wo) B, the view factor Ft applied per surfel (hard discs)
  // or per pixel from the blended normal (surfel_normalise_fs.glsl); alpha 2 marks linear
  // radiance for the composite.
  vec3 surfelB = texelFetch(surfelRadiance,
    ivec2(gl_VertexID % surfelListWidth, gl_VertexID / surfelListWidth), 0).rgb;
  colour = vec4(surfelB, 2.0);
  viewFactor = fresnelTransmittanceRGB(cosOut);
