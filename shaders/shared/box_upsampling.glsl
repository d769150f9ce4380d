// The naive comparison mode of Pérez García 2024 (sRAT-RT): an RGB albedo read as a box
// spectrum, its blue below 495 nm, its green from 495 to 570 nm, its red from 570 nm. Kept to
// show what smooth upsampling buys. Expects an albedo already in [0, 1].
const float kBoxBlueGreenNm = 495.0f;
const float kBoxGreenRedNm = 570.0f;

PRISM_INLINE float boxReflectance(IN(vec3) rgb, float lambdaNm) {
  if (lambdaNm < kBoxBlueGreenNm) return rgb.z;
  if (lambdaNm < kBoxGreenRedNm) return rgb.y;
  return rgb.x;
}

PRISM_INLINE vec4 boxReflectance4(IN(vec3) rgb, IN(vec4) lambdaNm) {
  return vec4(boxReflectance(rgb, lambdaNm.x), boxReflectance(rgb, lambdaNm.y),
              boxReflectance(rgb, lambdaNm.z), boxReflectance(rgb, lambdaNm.w));
}
