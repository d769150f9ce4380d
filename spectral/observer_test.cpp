#include "spectral/observer.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"

namespace prism {
namespace {

TEST(Observer, Cie1931YBarPeaksAt555) {
  const Observer& o = observer("cie1931");
  EXPECT_FALSE(o.isCamera);
  EXPECT_NEAR(o.at(555.0).y(), 1.0, 1e-4);
}

TEST(Observer, EqualEnergyWhiteHasEqualIntegrals) {
  // The CIE 1931 and 1964 CMFs are normalised so that illuminant E has X = Y = Z.
  for (const char* name : {"cie1931", "cie1964"}) {
    Eigen::Vector3d xyz = observer(name).integrate(Spectrum::constant(1.0));
    EXPECT_NEAR(xyz.x() / xyz.y(), 1.0, 2e-3) << name;
    EXPECT_NEAR(xyz.z() / xyz.y(), 1.0, 2e-3) << name;
  }
}

TEST(Observer, EveryCameraInDataIsAnObserver) {
  std::vector<std::string> cameras = listCameras();
  EXPECT_EQ(cameras.size(), 20u);
  for (const std::string& name : cameras) {
    const Observer& cam = observer(name);
    EXPECT_TRUE(cam.isCamera);
    Eigen::Vector3d response = cam.integrate(Spectrum::constant(1.0));
    EXPECT_TRUE((response.array() > 0.0).all()) << name;
  }
  EXPECT_EQ(listObservers().size(), 22u);
}

TEST(Observer, CameraOutsideItsMeasuredBandIsZero) {
  const Observer& cam = observer("nikon_d850");  // measured 380–720 nm
  EXPECT_EQ(cam.at(370.0).norm(), 0.0);
  EXPECT_EQ(cam.at(750.0).norm(), 0.0);
}

TEST(Observer, UnknownNameIsAnError) { EXPECT_THROW(observer("cie1932"), Error); }

TEST(Observer, ReflectanceWeightsReproduceTheTristimulus) {
  const Observer& cie = observer("cie1931");
  Spectrum light = Spectrum::fromFunction([](double l) { return 50.0 + 0.1 * l; });
  Spectrum r = Spectrum::fromFunction([](double l) { return 0.5 + 0.4 * std::sin(l / 40.0); });
  std::vector<Eigen::Vector3d> w = reflectanceWeights(cie, light);
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (int i = 0; i < kSpectrumSamples; ++i) sum += w[static_cast<std::size_t>(i)] * r[i];
  EXPECT_TRUE(sum.isApprox(reflectanceTristimulus(cie, r, light), 1e-12));
}

TEST(Observer, PerfectWhiteHasYOne) {
  Spectrum d65 = Spectrum::constant(1.0);
  EXPECT_NEAR(whiteTristimulus(observer("cie1931"), d65).y(), 1.0, 1e-12);
}

}  // namespace
}  // namespace prism
