  // Step 3 (eq. 14, 16): Lo = Ft(eta, wo) B; alpha 2 marks linear radiance for the composite.
  vec3 surfelB = texelFetch(surfelRadiance,
    ivec2(gl_VertexID % surfelListWidth, gl_VertexID / surfelListWidth), 0).rgb;
  colour = vec4(fresnelTransmittanceRGB(cosOut) * surfelB, 2.0);
