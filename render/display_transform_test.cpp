// A camera observer's image shown on a display: its raw RGB through a matrix fitted under the
// scene's light, so that under a narrow or spiky lamp the image keeps the light's colour and
// luminance (a matrix fitted under D65 gave the blue LED's camera response negative luminance —
// a black PNG), and white balance to a light makes a grey lit by it neutral through the camera too
// (its white was CIE 1931's: pink under a 520 nm LED).
#include <gtest/gtest.h>

#include "render/display_transform.h"
#include "spectral/illuminant.h"
#include "spectral/observer.h"

namespace prism::render {
namespace {

// What the renderer writes for a grey of reflectance 0.5 lit by `light`: the observer's tristimulus
// on its absolute scale (absoluteTristimulusScale), unnormalised.
glm::vec3 greyUnder(const Observer& obs, const Spectrum& light) {
  const Eigen::Vector3d t = obs.integrate(light) * (0.5 * absoluteTristimulusScale(obs));
  return glm::vec3(static_cast<float>(t.x()), static_cast<float>(t.y()), static_cast<float>(t.z()));
}

TEST(CameraDisplay, ACameraShowsANarrowLightAsTheEyeDoes) {
  for (const char* lamp : {"led:450:20", "led:520:30", "led-globe-a19", "F11", "A", "D65"}) {
    const Spectrum light = illuminant(lamp);
    const glm::vec3 eye = greyUnder(cie1931Observer(), light);
    for (const char* name : {"nikon_d850", "canon_eos_5d_mkiv", "sony_ilce_9"}) {
      const Observer& camera = observer(name);
      DisplaySettings settings;
      const DisplayTransform t = displayTransform(settings, resolveDisplay(settings, camera, &light), 0.0f);
      const glm::vec3 xyz = t.toXyz * greyUnder(camera, light);
      // Luminance within 3 % and chromaticity within 0.01 of the eye's (a 3 × 3 matrix fitted on 24
      // patches cannot be exact; a D65 fit gave the blue LED luminance of the wrong sign).
      EXPECT_NEAR(xyz.y / eye.y, 1.0f, 0.03f) << lamp << ", " << name;
      const float sum = xyz.x + xyz.y + xyz.z, eyeSum = eye.x + eye.y + eye.z;
      EXPECT_NEAR(xyz.x / sum, eye.x / eyeSum, 0.01f) << lamp << ", " << name;
      EXPECT_NEAR(xyz.y / sum, eye.y / eyeSum, 0.01f) << lamp << ", " << name;
    }
  }
}

TEST(CameraDisplay, WhiteBalanceToTheLightShowsItsGreyNeutral) {
  for (const char* lamp : {"led:520:30", "led-globe-a19", "F2", "A"}) {
    const Spectrum light = illuminant(lamp);
    for (const char* name : {"cie1931", "cie1964", "nikon_d850", "sony_ilce_9"}) {
      const Observer& obs = observer(name);
      DisplaySettings settings;
      settings.whiteBalance = lamp;
      settings.ev100 = 0.0f;
      const DisplayTransform t = displayTransform(settings, resolveDisplay(settings, obs, &light), 0.0f);
      const glm::vec3 rgb = t.toDisplay * greyUnder(obs, light);
      EXPECT_NEAR(rgb.x / rgb.y, 1.0f, 0.01f) << lamp << ", " << name;
      EXPECT_NEAR(rgb.z / rgb.y, 1.0f, 0.01f) << lamp << ", " << name;
    }
  }
}

}  // namespace
}  // namespace prism::render
