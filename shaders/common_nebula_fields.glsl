// Reading the nebula's per-voxel grids on the GPU as the CPU's VoxelField::sample does
// (techniques/nebula/nebula_precomputed.h): texelFetch at the eight voxel centres around a point and
// the weights of shared/nebula_march.glsl's axis, not the sampler's trilinear filtering, whose
// weights hardware quantises (to 1/256 on most GPUs). The march (passes/nebula_march.comp) and the
// lighting pass's star light (common_nebula_lighting.glsl) read the grids through it.
// Requires: shared/prelude.glsl, shared/nebula_march.glsl

// Where a point falls in the grid: the corners and weights along each axis.
struct Cell {
  ivec3 i0;
  ivec3 i1;
  vec3 f;
};

Cell cellAt(vec3 p, ivec3 n) {
  Cell c;
  for (int a = 0; a < 3; ++a) {
    int i0;
    int i1;
    float f;
    nebulaTrilinearAxis(p[a], n[a], i0, i1, f);
    c.i0[a] = i0;
    c.i1[a] = i1;
    c.f[a] = f;
  }
  return c;
}

// VoxelField::sample for four values of slab `slab`: Σ over corners (x outer, z inner) of the
// corner's weight × its values.
vec4 fieldOf(sampler3D field, Cell c, int slab, int nz) {
  ivec3 i[2] = ivec3[2](c.i0, c.i1);
  vec3 w[2] = vec3[2](vec3(1.0f) - c.f, c.f);
  vec4 sum = vec4(0.0f);
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b)
      for (int d = 0; d < 2; ++d)
        sum += (w[a].x * w[b].y * w[d].z) * texelFetch(field, ivec3(i[a].x, i[b].y, i[d].z + slab * nz), 0);
  return sum;
}
