// Run-time RGB → Jakob–Hanika coefficients on the GPU (GLSL only: it samples a texture). The
// table is one res × res × 3·res texture (blocks along z), uploaded by
// render/upsampling_texture.h; all index arithmetic is shared with the CPU in
// shared/upsampling.glsl. Include after shared/prelude.glsl and shared/upsampling.glsl.

// The reference: eight texel fetches blended with weights linear in the ratios and brightness.
vec3 upsamplingCoefficientsManual(sampler3D table, int res, vec3 rgb) {
  LutCell c = lutCell(lutPosition(rgb), res);
  int z0 = c.block * res + c.zi;
  vec3 c000 = texelFetch(table, ivec3(c.xi, c.yi, z0), 0).xyz;
  vec3 c100 = texelFetch(table, ivec3(c.xi + 1, c.yi, z0), 0).xyz;
  vec3 c010 = texelFetch(table, ivec3(c.xi, c.yi + 1, z0), 0).xyz;
  vec3 c110 = texelFetch(table, ivec3(c.xi + 1, c.yi + 1, z0), 0).xyz;
  vec3 c001 = texelFetch(table, ivec3(c.xi, c.yi, z0 + 1), 0).xyz;
  vec3 c101 = texelFetch(table, ivec3(c.xi + 1, c.yi, z0 + 1), 0).xyz;
  vec3 c011 = texelFetch(table, ivec3(c.xi, c.yi + 1, z0 + 1), 0).xyz;
  vec3 c111 = texelFetch(table, ivec3(c.xi + 1, c.yi + 1, z0 + 1), 0).xyz;
  return lutTrilinear(c000, c100, c010, c110, c001, c101, c011, c111, c.weight);
}

// One hardware-filtered fetch (the texture must use GL_LINEAR).
vec3 upsamplingCoefficientsFiltered(sampler3D table, int res, vec3 rgb) {
  return textureLod(table, lutFilteredCoordinate(lutPosition(rgb), res), 0.0).xyz;
}
