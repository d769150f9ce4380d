// Transfer functions between linear light and encoded signal, per channel, in [0, 1].
// Inputs below 0 are encoded as 0 (a negative signal has no meaning on a display); gamut
// handling happens before encoding.

// IEC 61966-2-1:1999 (sRGB), Eq. in §5.2; also the transfer of Display P3.
PRISM_INLINE float srgbEncode(float linear) {
  if (linear <= 0.0031308f) return 12.92f * max(linear, 0.0f);
  return 1.055f * pow(linear, 1.0f / 2.4f) - 0.055f;
}

PRISM_INLINE float srgbDecode(float encoded) {
  if (encoded <= 0.04045f) return max(encoded, 0.0f) / 12.92f;
  return pow((encoded + 0.055f) / 1.055f, 2.4f);
}

// ITU-R BT.2020-2 Table 4 (the BT.709 curve with 12-bit-accurate constants).
PRISM_INLINE float bt2020Encode(float linear) {
  const float alpha = 1.09929682680944f;
  const float beta = 0.018053968510807f;
  if (linear < beta) return 4.5f * max(linear, 0.0f);
  return alpha * pow(linear, 0.45f) - (alpha - 1.0f);
}

PRISM_INLINE float bt2020Decode(float encoded) {
  const float alpha = 1.09929682680944f;
  const float beta = 0.018053968510807f;
  if (encoded < 4.5f * beta) return max(encoded, 0.0f) / 4.5f;
  return pow((encoded + (alpha - 1.0f)) / alpha, 1.0f / 0.45f);
}

PRISM_INLINE vec3 srgbEncode3(IN(vec3) linear) {
  return vec3(srgbEncode(linear.x), srgbEncode(linear.y), srgbEncode(linear.z));
}

PRISM_INLINE vec3 srgbDecode3(IN(vec3) encoded) {
  return vec3(srgbDecode(encoded.x), srgbDecode(encoded.y), srgbDecode(encoded.z));
}

PRISM_INLINE vec3 bt2020Encode3(IN(vec3) linear) {
  return vec3(bt2020Encode(linear.x), bt2020Encode(linear.y), bt2020Encode(linear.z));
}

PRISM_INLINE vec3 bt2020Decode3(IN(vec3) encoded) {
  return vec3(bt2020Decode(encoded.x), bt2020Decode(encoded.y), bt2020Decode(encoded.z));
}
