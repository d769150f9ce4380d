// Display transform of the post pass, after exposure and the XYZ → display-RGB matrix (which
// includes white balance): out-of-gamut compression, a tone map, then the colour's own hue given
// back. The encode to the display's transfer function is transfer.glsl's.
// Requires: transfer.glsl cielab.glsl

const int kToneMapNone = 0;      // clip to [0, 1]
const int kToneMapReinhard = 1;  // x / (1 + x) on luminance, hue and saturation kept
const int kToneMapAces = 2;      // Narkowicz 2015's fit of the ACES RRT + ODT, per channel

// Exposure at ISO 100 (Lagarde & de Rousiers 2014, "Moving Frostbite to PBR", §5.1): a scene
// luminance of 1.2·2^EV100 cd/m² maps to 1 before the tone map (display white without one;
// ACES puts 1 at 0.80 and reaches white near 7).
PRISM_INLINE float exposureScale(float ev100) { return 1.0f / (1.2f * exp2(ev100)); }

// Colours a spectrum puts outside the display gamut have negative components. Rule: mix the
// colour towards the grey of the same luminance Y (weights = the display's Y row) just far
// enough that the smallest component is 0. Luminance and hue angle are kept, saturation is
// lost; never NaN for finite input (a black or grey colour is returned unchanged).
PRISM_INLINE vec3 compressToGamut(IN(vec3) rgb, IN(vec3) luminanceWeights) {
  float y = max(dot(rgb, luminanceWeights), 0.0f);
  float lowest = min(rgb.x, min(rgb.y, rgb.z));
  if (lowest >= 0.0f) return rgb;
  if (y <= 0.0f) return vec3(0.0f);
  float t = y / (y - lowest);  // mix(grey, rgb, t) has its lowest component at 0
  return vec3(y) + (rgb - vec3(y)) * t;
}

PRISM_INLINE vec3 toneMapReinhard(IN(vec3) rgb, IN(vec3) luminanceWeights) {
  float y = dot(rgb, luminanceWeights);
  if (y <= 0.0f) return vec3(0.0f);
  return rgb * (1.0f / (1.0f + y));
}

// Total: the fit passes 1 (white) near x = 7 and tends to 2.51/2.43 > 1; capping x at 1e4 keeps
// x² finite in float however overexposed the pixel (2^70 would make ∞/∞ = NaN, i.e. black).
PRISM_INLINE float acesFilmic(float x) {
  x = min(x, 1e4f);
  return clamp((x * (2.51f * x + 0.03f)) / (x * (2.43f * x + 0.59f) + 0.14f), 0.0f, 1.0f);
}

PRISM_INLINE vec3 toneMap(int op, IN(vec3) rgb, IN(vec3) luminanceWeights) {
  if (op == kToneMapReinhard) {
    return clamp(toneMapReinhard(rgb, luminanceWeights), vec3(0.0f), vec3(1.0f));
  }
  if (op == kToneMapAces) return vec3(acesFilmic(rgb.x), acesFilmic(rgb.y), acesFilmic(rgb.z));
  return clamp(rgb, vec3(0.0f), vec3(1.0f));
}

PRISM_INLINE bool insideDisplay(IN(vec3) rgb) {
  const float slack = 1e-4f;
  return min(rgb.x, min(rgb.y, rgb.z)) >= -slack && max(rgb.x, max(rgb.y, rgb.z)) <= 1.0f + slack;
}

// A tone map per channel (ACES), or a clip, turns the hue of a colour whose channels reach the
// display's top at different exposures: a 450 nm light's blue stops at 1 while its red keeps
// growing, and the light shows magenta. Rule: keep the mapped colour's CIELAB lightness and
// chroma, give it the hue angle of `light` (the exposed colour before gamut compression and tone
// map: the hue the spectrum has), and lower the chroma at that lightness and hue until the colour
// fits the display (bisection, 14 steps; grey always fits). So an over-exposed colour goes towards
// the display white along its own CIELAB hue. CIELAB is taken relative to the display white
// (displayToXyz · (1, 1, 1)); a colour without chroma is returned as mapped.
PRISM_INLINE vec3 keepHue(IN(vec3) mapped, IN(vec3) light, IN(mat3) displayToXyz, IN(mat3) xyzToDisplay) {
  vec3 white = displayToXyz * vec3(1.0f);
  vec3 lightLab = xyzToLab(displayToXyz * light, white);
  vec3 lab = xyzToLab(displayToXyz * mapped, white);
  float lightChroma = length(vec2(lightLab.y, lightLab.z));
  float chroma = length(vec2(lab.y, lab.z));
  if (!(lightChroma > 1e-3f) || !(chroma > 1e-3f)) return mapped;
  vec2 hue = vec2(lightLab.y, lightLab.z) / lightChroma;
  vec3 best = xyzToDisplay * labToXyz(vec3(lab.x, 0.0f, 0.0f), white);
  float lo = 0.0f;
  float hi = chroma;
  for (int i = 0; i < 15; ++i) {
    float c = i == 0 ? hi : 0.5f * (lo + hi);
    vec3 rgb = xyzToDisplay * labToXyz(vec3(lab.x, c * hue.x, c * hue.y), white);
    if (insideDisplay(rgb)) {
      best = rgb;
      lo = c;
      if (i == 0) break;
    } else {
      hi = c;
    }
  }
  return clamp(best, vec3(0.0f), vec3(1.0f));
}

// Tristimulus → display, all of the post pass but the dither and the final clamp (the pass dithers
// before it clamps): display RGB (exposure folded into toDisplay), gamut compression, tone map,
// the light's hue kept (keepHue), transfer (0 sRGB curve, 1 BT.2020). displayToXyz and
// xyzToDisplay are the display's primaries alone (no exposure); its second row weighs luminance.
// NaN or ∞ in, which nothing upstream should make, show black rather than whatever a driver's
// clamp makes of them; a finite colour whose exposure overflows float shows white, as the
// brightest colour does.
PRISM_INLINE vec3 encodeForDisplay(IN(mat3) toDisplay, IN(mat3) displayToXyz, IN(mat3) xyzToDisplay,
                                   int toneMapOp, int transfer, IN(vec3) tristimulus) {
  vec3 luminanceWeights = vec3(displayToXyz[0][1], displayToXyz[1][1], displayToXyz[2][1]);
  vec3 t = tristimulus;
  if (any(isnan(t)) || any(isinf(t))) t = vec3(0.0f);
  vec3 exposed = toDisplay * t;
  bool overflow = any(isnan(exposed)) || any(isinf(exposed));
  if (overflow) exposed = vec3(1e30f);
  vec3 rgb = compressToGamut(exposed, luminanceWeights);
  rgb = toneMap(toneMapOp, rgb, luminanceWeights);
  if (!overflow) rgb = keepHue(rgb, exposed, displayToXyz, xyzToDisplay);
  return transfer == 1 ? bt2020Encode3(rgb) : srgbEncode3(rgb);
}

// Triangular-distributed dither of ±1 LSB at 8 bits from two uniform numbers, added before
// quantisation so smooth gradients do not band.
PRISM_INLINE float ditherOffset(float u1, float u2) { return (u1 + u2 - 1.0f) / 255.0f; }
