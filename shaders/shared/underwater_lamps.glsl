// A lamp's light that the water scatters once into a view ray: the glow around a diver's torch
// and the shaft of its beam, which the closed form of underwater.glsl (light from above the
// surface) does not hold. A point or spot lamp of radiant intensity I(ω) at L lights a point p of
// the ray, s metres from the camera along d, with I/|L − p|² through e^(−σt·r_w), r_w the part of
// |L − p| under the surface (shareBelowSurface), and p sends σs/(4π) of it towards the camera,
// which it reaches through e^(−σt·s):
//   L_lamp = σs/(4π) ∫ I(p)/|L − p|² · e^(−σt·(s + r_w(s))) ds   over the ray's part in the water
// (isotropic scattering, as the path tracer's water; the lamp's shadow map, where it has one,
// dims each node: pixel_shading.glsl's lampsInWater).
// Equiangular substitution (Kulla & Fajardo 2012): with t_c the ray's closest approach to L and h
// its distance there, s = t_c + h·tan θ turns ds/|L − p|² into dθ/h, so the integrand left is
// bounded and smooth; 16 Gauss–Legendre nodes (two halves of 8) over θ. A spot's cone is first
// intersected with the ray, so that the nodes fall where its beam is.
// Requires: lights.glsl underwater.glsl

// Node i of 8-point Gauss–Legendre on [0, 1] (x) and its weight (y).
PRISM_INLINE vec2 gaussLegendre8(int i) {
  float x = 0.0f;
  float w = 0.0f;
  int k = i < 4 ? 3 - i : i - 4;  // the pair's index from the middle out: nodes ascend with i
  if (k == 0) { x = 0.1834346424956498f; w = 0.3626837833783620f; }
  if (k == 1) { x = 0.5255324099163290f; w = 0.3137066458778873f; }
  if (k == 2) { x = 0.7966664774136267f; w = 0.2223810344533745f; }
  if (k == 3) { x = 0.9602898564975363f; w = 0.1012285362903763f; }
  float node = i < 4 ? -x : x;
  return vec2(0.5f + 0.5f * node, 0.5f * w);
}

// Whether the direction q from a spot's apex lies inside its outer cone about `axis` (unit); q is
// scaled first, so that a point 1e30 m along a ray tests as it should.
PRISM_INLINE bool insideSpotCone(IN(vec3) q, IN(vec3) axis, float cosOuter) {
  float scale = max(max(abs(q.x), abs(q.y)), max(abs(q.z), 1e-30f));
  vec3 u = q / scale;
  return dot(u, axis) > cosOuter * length(u);
}

// The span [x, y] of the ray origin + s·dir, s in [0, lengthM], inside a spot's outer cone (its
// forward nappe, convex for cosOuter > 0: one span, empty where x ≥ y). The cone's surface cuts the
// ray where A·s² + B·s + C = 0; between those cuts, the ends and the ray's closest approach to the
// apex, each piece is in or out whole. (A ray through the apex along the axis, a torch seen head
// on, touches the surface only there: the double root that rounding may lose, which the closest
// approach stands in for.)
PRISM_INLINE vec2 spotConeSpan(IN(vec3) origin, IN(vec3) dir, float lengthM, IN(vec3) apex, IN(vec3) axis,
                               float cosOuter) {
  if (cosOuter <= 0.0f) return vec2(0.0f, lengthM);
  vec3 o = origin - apex;
  float a = dot(dir, axis);
  float b = dot(o, axis);
  float c2 = cosOuter * cosOuter;
  // a² − cos² and b² − cos²·|o|² as products of a difference and a sum: for a ray nearly along the
  // cone's side the difference of squares lost A to 0 in float, and the far cut with it.
  float oLength = length(o);
  float qa = (a - cosOuter) * (a + cosOuter);
  float qb = 2.0f * (a * b - c2 * dot(o, dir));
  float qc = (b - cosOuter * oLength) * (b + cosOuter * oLength);
  float cuts[5];
  int n = 0;
  cuts[n++] = 0.0f;
  float closest = -dot(o, dir);
  if (closest > 0.0f && closest < lengthM) cuts[n++] = closest;
  float roots[2];
  int rootCount = 0;
  if (abs(qa) < 1e-7f * max(abs(qb), 1.0f)) {
    if (abs(qb) > 0.0f) roots[rootCount++] = -qc / qb;
  } else {
    float disc = qb * qb - 4.0f * qa * qc;
    if (disc >= 0.0f) {
      float q = -0.5f * (qb + (qb < 0.0f ? -sqrt(disc) : sqrt(disc)));  // no cancellation
      roots[rootCount++] = q / qa;
      if (abs(q) > 0.0f) roots[rootCount++] = qc / q;
    }
  }
  for (int r = 0; r < rootCount; ++r)
    if (roots[r] > 0.0f && roots[r] < lengthM) cuts[n++] = roots[r];
  cuts[n++] = lengthM;
  // Each cut and the next one after it, without sorting (an insertion sort of these five lost
  // the span on llvmpipe: a torch's beam crossing the view gave nothing there, and 12 % of a pixel
  // against the CPU twin). Each piece is tested a bounded way into it, not at its middle: where
  // rounding lost a far cut, an endless piece's middle lies 5e29 m off, where only the ray's
  // direction counts, and a ray along the cone's side was then taken as outside all the way.
  vec2 span = vec2(lengthM, 0.0f);
  for (int i = 0; i < n; ++i) {
    float next = lengthM;
    for (int j = 0; j < n; ++j)
      if (cuts[j] > cuts[i]) next = min(next, cuts[j]);
    float probe = cuts[i] + min(0.5f * (next - cuts[i]), 1.0f + cuts[i]);
    if (next > cuts[i] && insideSpotCone(o + dir * probe, axis, cosOuter)) {
      span.x = min(span.x, cuts[i]);
      span.y = max(span.y, next);
    }
  }
  return span;
}

// A lamp's in-scattering along a ray is a sum over 16 nodes of weight · e^(−σt·path), times
// σs·scale: the nodes' weights (the rule's, times the spot's falloff), the paths the light travels
// in the water to each and on to the ray's origin, and the scale do not depend on the wavelength.
// lampRay works out what the nodes share, once per pixel and lamp; lampNode each node, once for
// every batch of wavelengths.
const int kLampNodeCount = 16;
struct LampRay {
  float closest;  // along the ray to its closest approach to the lamp
  float h;        // the ray's distance from the lamp there
  float tBegin;   // tan θ at the span's beginning
  float width;    // the span's angle Δθ
  float scale;    // I·Δθ/(4π·h); 0 where the ray misses the beam
};

// The lamp (kLightPoint or kLightSpot, lights.glsl's parameters) seen along the ray from `origin`
// along the unit `dir` over its first lengthM metres (all under water).
PRISM_INLINE LampRay lampRay(IN(vec3) origin, IN(vec3) dir, float lengthM, int type, IN(vec3) lampPosition,
                             IN(vec3) spotAxis, float intensity, float cosOuter) {
  LampRay r;
  r.closest = 0.0f;
  r.h = 1.0f;
  r.tBegin = 0.0f;
  r.width = 0.0f;
  r.scale = 0.0f;
  vec2 span = type == kLightSpot ? spotConeSpan(origin, dir, lengthM, lampPosition, spotAxis, cosOuter)
                                 : vec2(0.0f, lengthM);
  if (!(span.y > span.x)) return r;
  PRISM_PRECISE vec3 toLamp = lampPosition - origin;
  r.closest = dot(toLamp, dir);
  r.h = max(length(toLamp - dir * r.closest), 1e-3f);  // a ray through the lamp: 1 mm from it
  // θ from the closest approach, tan θ = (s − closest)/h, up to 1e15 (float's π/2). The span's
  // angle from the atan of the tangents' difference, and each node's s from the tangent of a sum:
  // a narrow beam's few milliradians are not the difference of two angles near π/2, whose digits
  // a float atan rounds away.
  r.tBegin = clamp((span.x - r.closest) / r.h, -1e15f, 1e15f);
  float tEnd = clamp((span.y - r.closest) / r.h, -1e15f, 1e15f);
  r.width = atan(tEnd - r.tBegin, 1.0f + r.tBegin * tEnd);
  r.scale = intensity * r.width / (4.0f * kPi * r.h);
  return r;
}

// Node n (< kLampNodeCount) of the ray's lamp.
struct LampNode {
  float weight;
  float pathM;    // the path its light travels in the water: from the lamp (the part under the surface) and on to the ray's origin
  vec3 position;  // where it lies (the lamp's shadow is looked up there)
};
PRISM_INLINE LampNode lampNode(IN(LampRay) r, int n, IN(vec3) origin, IN(vec3) dir, int type, IN(vec3) lampPosition,
                               IN(vec3) spotAxis, float cosInner, float cosOuter, float surfaceY) {
  vec2 node = gaussLegendre8(n % 8);
  // tan(θBegin + φ) = (tBegin·cos φ + sin φ)/(cos φ − tBegin·sin φ), whose denominator,
  // cos(θBegin + φ)/cos θBegin, stays above 0: tan φ itself is infinite at φ = π/2.
  float phi = r.width * 0.5f * (float(n / 8) + node.x);
  float sinPhi = sin(phi);
  float cosPhi = cos(phi);
  float s = r.closest + r.h * (r.tBegin * cosPhi + sinPhi) / (cosPhi - r.tBegin * sinPhi);
  PRISM_PRECISE vec3 p = origin + dir * s;
  LightIncidence li = lightIncidence(type, lampPosition, spotAxis, 1.0f, cosInner, cosOuter, p);
  float profile = li.irradiance * li.distance * li.distance;  // the spot's falloff; 1 for a point lamp
  LampNode result;
  result.weight = node.y * 0.5f * profile;
  result.pathM = s + li.distance * shareBelowSurface(p.y, lampPosition.y, surfaceY);
  result.position = p;
  return result;
}
