// Percentage-closer filtering of a shadow map (Reeves et al. 1987): the fraction of a 3×3 grid
// of bilinear depth comparisons that sees the light, i.e. a tent-shaped footprint over 4×4
// texels. Shared code only computes where to look and how to weigh; each side fetches the
// stored depths (texelFetch on the GPU, an array on the CPU).

struct ShadowFootprint {
  int x0;      // texel column of the footprint's first column
  int y0;      // texel row of the footprint's first row
  vec2 frac;   // position inside the central texel, for the bilinear weights
  float depth; // the receiver's depth in the light's [0, 1] depth range
  bool inside; // false outside the light's frustum: lit
};

// lightClip: the point in the light's clip space (after the shadow matrix, before the divide).
PRISM_INLINE ShadowFootprint shadowFootprint(IN(vec4) lightClip, int size) {
  ShadowFootprint f;
  PRISM_PRECISE vec3 ndc = vec3(lightClip.x, lightClip.y, lightClip.z) / lightClip.w;
  PRISM_PRECISE vec3 uvz = ndc * 0.5f + vec3(0.5f);
  f.inside = lightClip.w > 0.0f && uvz.x >= 0.0f && uvz.x <= 1.0f && uvz.y >= 0.0f &&
             uvz.y <= 1.0f && uvz.z <= 1.0f;
  f.x0 = 0;
  f.y0 = 0;
  f.frac = vec2(0.0f);
  f.depth = uvz.z;
  if (!f.inside) return f;  // before any float → int conversion of a far-off (or NaN) texel
  PRISM_PRECISE vec2 texel = vec2(uvz.x, uvz.y) * float(size) - vec2(0.5f);
  vec2 base = floor(texel);
  f.frac = texel - base;
  f.x0 = int(base.x) - 1;
  f.y0 = int(base.y) - 1;
  return f;
}

// Weight of footprint column (or row) i ∈ 0..3: the three bilinear taps at offsets −1, 0, +1
// cover weights (1 − f, 1, 1, f) / 3.
PRISM_INLINE float shadowTapWeight(int i, float frac) {
  if (i == 0) return (1.0f - frac) / 3.0f;
  if (i == 3) return frac / 3.0f;
  return 1.0f / 3.0f;
}

// Point lights: six perspective faces, a layer each from the light's first, looking along +x, −x,
// +y, −y, +z, −z; a point is looked up in the face of its direction's largest component. Each
// face sees a little more than its 90° (four texels a side), so that the 4×4 PCF footprint of a
// point on a seam stays inside the face. The shadow pass renders with these very matrices.
PRISM_INLINE int pointShadowFace(IN(vec3) fromLight) {
  vec3 a = abs(fromLight);
  int axis = a.x >= a.y && a.x >= a.z ? 0 : (a.y >= a.z ? 1 : 2);
  return 2 * axis + (fromLight[axis] >= 0.0f ? 0 : 1);
}

// A light's projection for its six faces, made once per light (the CPU's frame data): x the faces'
// 1 / tan(half-angle), four texels of margin on each side of the 90°; y and z the perspective's
// depth terms for the range [nearM, farM].
PRISM_INLINE vec3 pointShadowProjection(float nearM, float farM, int size) {
  return vec3(1.0f - 8.0f / float(size), -(farM + nearM) / (farM - nearM), -2.0f * farM * nearM / (farM - nearM));
}

// World → face's clip space: the view basis (right r, up u, back z = −forward) and the perspective
// of a square frustum of half-width 1/projection.x, as lookAt and perspective would build them.
PRISM_INLINE mat4 pointShadowFromWorld(IN(vec3) lightPosition, int face, IN(vec3) projection) {
  int axis = face / 2;
  vec3 forward = vec3(0.0f);
  forward[axis] = face % 2 == 0 ? 1.0f : -1.0f;
  vec3 u = axis == 1 ? vec3(0.0f, 0.0f, 1.0f) : vec3(0.0f, 1.0f, 0.0f);
  vec3 z = -forward;
  vec3 r = cross(u, z);
  float scale = projection.x, a = projection.y;
  PRISM_PRECISE float tz = projection.z - a * dot(z, lightPosition);
  return mat4(vec4(scale * r.x, scale * u.x, a * z.x, forward.x), vec4(scale * r.y, scale * u.y, a * z.y, forward.y),
              vec4(scale * r.z, scale * u.z, a * z.z, forward.z),
              vec4(-scale * dot(r, lightPosition), -scale * dot(u, lightPosition), tz, -dot(forward, lightPosition)));
}

// A directional light's cascades (parallel-split shadow maps, Zhang et al. 2006): layers fitted to
// slices of the camera's view, finest first, the last the whole scene's map. A window (x, y, s)
// maps the whole-scene map's clip x, y to its cascade's, (x − window.x, y − window.y)·s: world →
// the cascade's clip space. The shadow pass renders with these very matrices.
PRISM_INLINE mat4 shadowCascadeFromWorld(IN(mat4) wholeScene, IN(vec4) window) {
  mat4 m = wholeScene;
  for (int j = 0; j < 4; ++j) {
    m[j].x = window.z * (wholeScene[j].x - window.x * wholeScene[j].w);
    m[j].y = window.z * (wholeScene[j].y - window.y * wholeScene[j].w);
  }
  return m;
}

// 1 when the receiver (with its bias) is no farther from the light than the stored occluder.
PRISM_INLINE float shadowTest(float storedDepth, float receiverDepth, float bias) {
  return receiverDepth - bias <= storedDepth ? 1.0f : 0.0f;
}
