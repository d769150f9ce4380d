// Irradiance from one analytic light at a surface point, before the surface's cosine: the
// light's photometric amount (lux for a directional light, candela for point and spot lights,
// see render/scene.h) times its geometric falloff. Multiplied by the light's normalised SPD per
// wavelength, it gives spectral irradiance on a surface facing the light.

const int kLightDirectional = 0;
const int kLightPoint = 1;
const int kLightSpot = 2;

struct LightIncidence {
  vec3 toLight;       // unit direction from the point towards the light
  float irradiance;   // on a surface facing the light
  float distance;     // to the light (0 for directional)
};

// directionTravel: the way the light travels (directional, spot). Spot cones are cosines of
// the half-angles, cosOuter < cosInner; the falloff between them is smoothstep in the cosine.
PRISM_INLINE LightIncidence lightIncidence(int type, IN(vec3) position, IN(vec3) directionTravel,
                                           float intensity, float cosInner, float cosOuter,
                                           IN(vec3) point) {
  LightIncidence li;
  if (type == kLightDirectional) {
    li.toLight = -directionTravel;
    li.irradiance = intensity;
    li.distance = 0.0f;
    return li;
  }
  vec3 d = position - point;
  float dist2 = max(dot(d, d), 1e-8f);
  li.distance = sqrt(dist2);
  li.toLight = d / li.distance;
  li.irradiance = intensity / dist2;  // inverse square law
  if (type == kLightSpot) {
    float cosAngle = dot(-li.toLight, directionTravel);
    float t = clamp((cosAngle - cosOuter) / max(cosInner - cosOuter, 1e-6f), 0.0f, 1.0f);
    li.irradiance *= t * t * (3.0f - 2.0f * t);
  }
  return li;
}
