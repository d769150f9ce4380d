#include "spectral/camera_matrix.h"

#include <gtest/gtest.h>

#include <Eigen/LU>

#include "spectral/illuminant.h"

namespace prism {
namespace {

TEST(CameraMatrix, RecoversAnExactLinearCamera) {
  // A "camera" whose curves are a linear mix of x̄ȳz̄ is fitted exactly by the inverse mix.
  const Observer& cie = observer("cie1931");
  Eigen::Matrix3d mix;
  mix << 0.9, 0.2, 0.0, 0.1, 0.8, 0.1, 0.0, 0.1, 1.1;
  Observer camera{"synthetic", true, {}};
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
      camera.curves[static_cast<std::size_t>(r)] += cie.curves[static_cast<std::size_t>(c)] * mix(r, c);
  Spectrum d65 = illuminant("D65");
  CameraMatrixFit fit = fitCameraToXyz(camera, d65, cie);
  // Camera values are normalised by their own G white, so the fit is mix⁻¹ up to that scale.
  double gWhite = camera.integrate(d65)[1] / cie.integrate(d65)[1];
  EXPECT_TRUE(fit.cameraToXyz.isApprox(mix.inverse() * gWhite, 1e-9)) << fit.cameraToXyz;
  EXPECT_LT(fit.maxDeltaE2000, 1e-3);
}

TEST(CameraMatrix, RealCamerasFitTheChartClosely) {
  Spectrum d65 = illuminant("D65");
  for (const char* name : {"nikon_d850", "canon_eos_5d_mkiv", "sony_ilce_7m3"}) {
    CameraMatrixFit fit = fitCameraToXyz(observer(name), d65, observer("cie1931"));
    EXPECT_LT(fit.meanDeltaE2000, 3.0) << name;
    EXPECT_GT(fit.meanDeltaE2000, 0.0) << name;  // real sensors are not colorimetric
    EXPECT_GT(fit.chartConditioning, kIllPosedCameraFit) << name;
  }
}

// A camera sees what its curves reach: not an LED past them, though a tail of it (1e-86 of its peak
// at 720 nm, where the D850's curves end) made its G 1e-89 rather than 0.
TEST(CameraMatrix, ACameraSeesWhatItsCurvesReach) {
  const Observer& d850 = observer("nikon_d850");
  for (const char* light : {"D65", "A", "led:450:20", "led:700:10"}) EXPECT_TRUE(cameraSees(d850, illuminant(light))) << light;
  for (const char* light : {"led:790:5", "led:830:1"}) EXPECT_FALSE(cameraSees(d850, illuminant(light))) << light;
}

// Under a narrow LED the chart's camera colours nearly share one direction: the fit says so.
TEST(CameraMatrix, ANarrowLightMakesTheFitIllPosed) {
  for (const char* light : {"led:450:20", "led:790:5"}) {
    CameraMatrixFit fit = fitCameraToXyz(observer("nikon_d850"), illuminant(light), observer("cie1931"));
    EXPECT_LT(fit.chartConditioning, kIllPosedCameraFit) << light;
  }
  EXPECT_GT(fitCameraToXyz(observer("nikon_d850"), illuminant("A"), observer("cie1931")).chartConditioning,
            kIllPosedCameraFit);
}

}  // namespace
}  // namespace prism
