// Looking up Jakob–Hanika coefficients for an RGB colour in Prism's precomputed table.
//
// Layout (Jakob & Hanika 2019, §4): three blocks, one per largest channel m of the colour. In
// block m the colour is (z, x·z, y·z) rotated so that z = rgb[m] is the brightness and
// x = rgb[m+1]/z, y = rgb[m+2]/z are ratios in [0, 1]. In z, nodes sit at
// scale(t) = smoothstep(smoothstep(t)), t = k/(res−1), crowding the darkest and brightest
// colours. Beyond the paper, x and y nodes sit at smoothstep(t) rather than t, crowding both
// ends: the coefficients change fastest for saturated colours (ratios near 0) and near white
// (ratios near 1). At res 64 for sRGB this took the worst round-trip error of trilinear
// interpolation from 0.47 ΔE00 (uniform ratios; 1.02 with t² nodes) to 0.10. Data order:
// [block][z][y][x] → (c0, c1, c2).
//
// Two run-time paths, both from this file:
// - manual (the reference): each interval comes analytically from the inverse of its node
//   mapping (no search), corrected by one comparison with the exact node values, and the
//   eight corners are blended with weights linear in x, y and z;
// - filtered: ratios and brightness are mapped into texel space through the inverse node
//   mappings, so the GPU's trilinear filter does the whole blend in one 3D fetch. It
//   interpolates linearly in node space rather than in x, y, z: a different (equally smooth)
//   interpolant between the same nodes.
// Inputs are albedos: NaN is read as 0 and channels are clamped to [0, 1] first.

// The manual path's node values, weights and blend are written out operation by operation, not
// with the built-ins smoothstep and mix, whose expansions differ: Mesa evaluates smoothstep as
// t·(t·(3 − 2t)) and mix as a + t·(b − a), GLM as (t·t)·(3 − 2t) and a·(1 − t) + b·t. Node values
// then differed by up to 3 ULP, which the z weight, a difference of nodes crowded near 0 and 1,
// amplified to 8e-6; and near saturated colours c2 reaches ±150 and cancels against c0·λ² + c1·λ,
// so one ULP of a coefficient (1.5e-5) is ~7e-6 of reflectance. Each alone made llvmpipe differ
// from the CPU by 3e-5 of reflectance; written out, the two agree bit for bit. In GLSL they are
// also `precise`, so that no driver fuses them into FMAs or reassociates them (the CPU build
// does neither).
// smoothstep(0, 1, t) as GLM evaluates it: t²·(3 − 2t).
PRISM_INLINE float lutSmoothstep(float t) {
  float c = clamp(t, 0.0f, 1.0f);
  PRISM_PRECISE float r = c * c * (3.0f - 2.0f * c);
  return r;
}

// mix(a, b, t) as GLM evaluates it: a·(1 − t) + b·t (exact at t = 0 and t = 1).
PRISM_INLINE vec3 lutMix(IN(vec3) a, IN(vec3) b, float t) {
  PRISM_PRECISE vec3 r = a * (1.0f - t) + b * t;
  return r;
}

PRISM_INLINE float lutScaleOfNode(float t) { return lutSmoothstep(lutSmoothstep(t)); }

// Inverse of y = 3x² − 2x³ on [0, 1]: x = ½ − sin(asin(1 − 2y)/3).
PRISM_INLINE float smoothstepInverse(float y) {
  return 0.5f - sin(asin(clamp(1.0f - 2.0f * y, -1.0f, 1.0f)) / 3.0f);
}

PRISM_INLINE float lutNodeOfScale(float z) { return smoothstepInverse(smoothstepInverse(z)); }

// Ratio axes: node i at smoothstep(i/(res−1)).
PRISM_INLINE float lutRatioOfNode(float t) { return lutSmoothstep(t); }
PRISM_INLINE float lutNodeOfRatio(float x) { return smoothstepInverse(x); }

struct LutPosition {
  int block;  // index of the largest channel
  float x;    // next channel / largest, in [0, 1]
  float y;    // channel after that / largest, in [0, 1]
  float z;    // the largest channel, in [0, 1]
};

PRISM_INLINE float sanitiseAlbedo(float v) { return isnan(v) ? 0.0f : clamp(v, 0.0f, 1.0f); }

PRISM_INLINE LutPosition lutPosition(IN(vec3) rgb) {
  vec3 c = vec3(sanitiseAlbedo(rgb.x), sanitiseAlbedo(rgb.y), sanitiseAlbedo(rgb.z));
  int block = 2;
  if (c.x >= c.y && c.x >= c.z) block = 0;
  else if (c.y >= c.z) block = 1;
  LutPosition p;
  p.block = block;
  p.z = c[block];
  p.x = p.z > 0.0f ? c[(block + 1) % 3] / p.z : 0.0f;
  p.y = p.z > 0.0f ? c[(block + 2) % 3] / p.z : 0.0f;
  return p;
}

// The manual path's cell: lower corner indices and the blend weights towards the upper corner.
struct LutCell {
  int block;
  int xi;
  int yi;
  int zi;
  vec3 weight;
};

PRISM_INLINE LutCell lutCell(IN(LutPosition) p, int res) {
  float last = float(res - 1);
  LutCell cell;
  cell.block = p.block;
  // Analytic indices (no search) can land one off at a node, and asin/sin differ between
  // drivers; the node values themselves, plain polynomials, decide.
  int xi = clamp(int(lutNodeOfRatio(p.x) * last), 0, res - 2);
  if (xi > 0 && p.x < lutRatioOfNode(float(xi) / last)) xi -= 1;
  if (xi < res - 2 && p.x >= lutRatioOfNode(float(xi + 1) / last)) xi += 1;
  int yi = clamp(int(lutNodeOfRatio(p.y) * last), 0, res - 2);
  if (yi > 0 && p.y < lutRatioOfNode(float(yi) / last)) yi -= 1;
  if (yi < res - 2 && p.y >= lutRatioOfNode(float(yi + 1) / last)) yi += 1;
  int zi = clamp(int(lutNodeOfScale(p.z) * last), 0, res - 2);
  if (zi > 0 && p.z < lutScaleOfNode(float(zi) / last)) zi -= 1;
  if (zi < res - 2 && p.z >= lutScaleOfNode(float(zi + 1) / last)) zi += 1;
  cell.xi = xi;
  cell.yi = yi;
  cell.zi = zi;
  float z0 = lutScaleOfNode(float(zi) / last);
  float z1 = lutScaleOfNode(float(zi + 1) / last);
  // Weights linear in the ratios and the brightness themselves between the nodes.
  float x0 = lutRatioOfNode(float(cell.xi) / last);
  float x1 = lutRatioOfNode(float(cell.xi + 1) / last);
  float y0 = lutRatioOfNode(float(cell.yi) / last);
  float y1 = lutRatioOfNode(float(cell.yi + 1) / last);
  PRISM_PRECISE float wx = (p.x - x0) / (x1 - x0);
  PRISM_PRECISE float wy = (p.y - y0) / (y1 - y0);
  PRISM_PRECISE float wz = (p.z - z0) / (z1 - z0);
  cell.weight = vec3(clamp(wx, 0.0f, 1.0f), clamp(wy, 0.0f, 1.0f), clamp(wz, 0.0f, 1.0f));
  return cell;
}

// Blend of the eight corners cXYZ (X, Y, Z ∈ {0, 1}: lower or upper index on that axis).
PRISM_INLINE vec3 lutTrilinear(IN(vec3) c000, IN(vec3) c100, IN(vec3) c010, IN(vec3) c110,
                               IN(vec3) c001, IN(vec3) c101, IN(vec3) c011, IN(vec3) c111,
                               IN(vec3) w) {
  vec3 c00 = lutMix(c000, c100, w.x);
  vec3 c10 = lutMix(c010, c110, w.x);
  vec3 c01 = lutMix(c001, c101, w.x);
  vec3 c11 = lutMix(c011, c111, w.x);
  return lutMix(lutMix(c00, c10, w.y), lutMix(c01, c11, w.y), w.z);
}

// The filtered path's normalised texture coordinate in a res × res × 3·res texture holding
// the three blocks one after another along z. Texel centres only ever blend within a block.
PRISM_INLINE vec3 lutFilteredCoordinate(IN(LutPosition) p, int res) {
  float n = float(res);
  float last = n - 1.0f;
  return vec3((lutNodeOfRatio(p.x) * last + 0.5f) / n, (lutNodeOfRatio(p.y) * last + 0.5f) / n,
              (float(p.block) * n + lutNodeOfScale(p.z) * last + 0.5f) / (3.0f * n));
}
