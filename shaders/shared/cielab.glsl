// CIELAB and the three CIE colour-difference formulas, per pixel (the viewer's ΔE heat map and
// the CPU reports use this same code).
//
// CIELAB: CIE 15:2004 §8.2.1, with the exact constants ε = 216/24389 and κ = 24389/27 of
// CIE 15:2004 Note 5 rather than the rounded 0.008856 / 903.3, so that f is continuous.
// ΔE*94: CIE 116-1995, graphic-arts weights (kL = 1, K1 = 0.045, K2 = 0.015).
// CIEDE2000: CIE 142-2001, in the form of Sharma, Wu & Dalal 2005, "The CIEDE2000
// Color-Difference Formula: Implementation Notes, Supplementary Test Data, and Mathematical
// Observations", Eqs. 1–20, kL = kC = kH = 1. Hues are in degrees as in that paper.

PRISM_INLINE float labF(float t) {
  const float epsilon = 216.0f / 24389.0f;
  const float kappa = 24389.0f / 27.0f;
  if (t > epsilon) return pow(t, 1.0f / 3.0f);
  return (kappa * t + 16.0f) / 116.0f;
}

// df/dt, for optimisers that work in CIELAB.
PRISM_INLINE float labFDerivative(float t) {
  const float epsilon = 216.0f / 24389.0f;
  const float kappa = 24389.0f / 27.0f;
  if (t > epsilon) return 1.0f / (3.0f * pow(t, 2.0f / 3.0f));
  return kappa / 116.0f;
}

// The white CIELAB divides by: each channel at least kLabWhiteFloor of its Y. A light that all but
// misses a channel (a far-red LED's Z, 1e-81 of its Y; none at all under a 700 nm line) gave a* or
// b* of ±∞ or NaN.
const float kLabWhiteFloor = 1e-6f;
PRISM_INLINE vec3 labWhite(IN(vec3) whiteXyz) { return max(whiteXyz, vec3(kLabWhiteFloor * whiteXyz.y)); }

// xyz and whiteXyz on the same scale (e.g. white Y = 1 or 100); returns (L*, a*, b*).
PRISM_INLINE vec3 xyzToLab(IN(vec3) xyz, IN(vec3) whiteXyz) {
  vec3 white = labWhite(whiteXyz);
  float fx = labF(xyz.x / white.x);
  float fy = labF(xyz.y / white.y);
  float fz = labF(xyz.z / white.z);
  return vec3(116.0f * fy - 16.0f, 500.0f * (fx - fy), 200.0f * (fy - fz));
}

PRISM_INLINE float labFInverse(float f) {
  const float epsilon = 216.0f / 24389.0f;
  const float kappa = 24389.0f / 27.0f;
  float cube = f * f * f;
  if (cube > epsilon) return cube;
  return (116.0f * f - 16.0f) / kappa;
}

PRISM_INLINE vec3 labToXyz(IN(vec3) lab, IN(vec3) whiteXyz) {
  float fy = (lab.x + 16.0f) / 116.0f;
  float fx = fy + lab.y / 500.0f;
  float fz = fy - lab.z / 200.0f;
  vec3 white = labWhite(whiteXyz);
  return vec3(labFInverse(fx) * white.x, labFInverse(fy) * white.y, labFInverse(fz) * white.z);
}

PRISM_INLINE float deltaE76(IN(vec3) lab1, IN(vec3) lab2) {
  vec3 d = lab1 - lab2;
  return sqrt(dot(d, d));
}

PRISM_INLINE float deltaE94(IN(vec3) lab1, IN(vec3) lab2) {
  float c1 = sqrt(lab1.y * lab1.y + lab1.z * lab1.z);
  float c2 = sqrt(lab2.y * lab2.y + lab2.z * lab2.z);
  float dL = lab1.x - lab2.x;
  float dC = c1 - c2;
  float da = lab1.y - lab2.y;
  float db = lab1.z - lab2.z;
  float dH2 = max(da * da + db * db - dC * dC, 0.0f);
  float sC = 1.0f + 0.045f * c1;
  float sH = 1.0f + 0.015f * c1;
  return sqrt(dL * dL + (dC / sC) * (dC / sC) + dH2 / (sH * sH));
}

// Hue angle in degrees in [0, 360); 0 for a neutral colour (Sharma Eq. 4).
PRISM_INLINE float hueDegrees(float b, float aPrime) {
  if (b == 0.0f && aPrime == 0.0f) return 0.0f;
  float h = degrees(atan(b, aPrime));
  return h < 0.0f ? h + 360.0f : h;
}

// √(C⁷ / (C⁷ + 25⁷)), the chroma weight of Sharma's G and R_C, written so that C⁷ never overflows
// float (it did above C ≈ 3e5: a pixel 1e15 times its white came out as ΔE00 inf, --lab 1e6 NaN).
PRISM_INLINE float chromaWeight7(float c) {
  if (c <= 25.0f) {
    float c7 = pow(c, 7.0f);
    return sqrt(c7 / (c7 + 6103515625.0f));
  }
  return sqrt(1.0f / (1.0f + pow(25.0f / c, 7.0f)));
}

PRISM_INLINE float deltaE2000(IN(vec3) lab1, IN(vec3) lab2) {
  float cStar1 = sqrt(lab1.y * lab1.y + lab1.z * lab1.z);
  float cStar2 = sqrt(lab2.y * lab2.y + lab2.z * lab2.z);
  float g = 0.5f * (1.0f - chromaWeight7(0.5f * (cStar1 + cStar2)));
  float a1 = (1.0f + g) * lab1.y;
  float a2 = (1.0f + g) * lab2.y;
  float c1 = sqrt(a1 * a1 + lab1.z * lab1.z);
  float c2 = sqrt(a2 * a2 + lab2.z * lab2.z);
  float h1 = hueDegrees(lab1.z, a1);
  float h2 = hueDegrees(lab2.z, a2);

  float dL = lab2.x - lab1.x;
  float dC = c2 - c1;
  float dh = 0.0f;
  if (c1 * c2 != 0.0f) {
    dh = h2 - h1;
    if (dh > 180.0f) dh -= 360.0f;
    else if (dh < -180.0f) dh += 360.0f;
  }
  float dH = 2.0f * sqrt(c1 * c2) * sin(radians(0.5f * dh));

  float lMean = 0.5f * (lab1.x + lab2.x);
  float cMean = 0.5f * (c1 + c2);
  float hMean = h1 + h2;
  if (c1 * c2 != 0.0f) {
    if (abs(h1 - h2) <= 180.0f) hMean = 0.5f * (h1 + h2);
    else if (h1 + h2 < 360.0f) hMean = 0.5f * (h1 + h2 + 360.0f);
    else hMean = 0.5f * (h1 + h2 - 360.0f);
  }
  float t = 1.0f - 0.17f * cos(radians(hMean - 30.0f)) + 0.24f * cos(radians(2.0f * hMean)) +
            0.32f * cos(radians(3.0f * hMean + 6.0f)) - 0.20f * cos(radians(4.0f * hMean - 63.0f));
  float dTheta = 30.0f * exp(-((hMean - 275.0f) / 25.0f) * ((hMean - 275.0f) / 25.0f));
  float rC = 2.0f * chromaWeight7(cMean);
  float lOff2 = (lMean - 50.0f) * (lMean - 50.0f);
  float sL = 1.0f + 0.015f * lOff2 / sqrt(20.0f + lOff2);
  float sC = 1.0f + 0.045f * cMean;
  float sH = 1.0f + 0.015f * cMean * t;
  float rT = -sin(radians(2.0f * dTheta)) * rC;
  float l = dL / sL;
  float c = dC / sC;
  float h = dH / sH;
  return sqrt(max(l * l + c * c + h * h + rT * c * h, 0.0f));
}
