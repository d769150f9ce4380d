#include "scene/conductors.h"

#include <gtest/gtest.h>

#include "core/error.h"

namespace prism {
namespace {

TEST(Conductors, EveryListedConductorLoads) {
  for (const std::string& name : listConductors()) {
    ConductorIor ior = conductorIor(name);
    EXPECT_EQ(ior.name, name);
    for (int i = 0; i < kSpectrumSamples; ++i) {
      EXPECT_GT(ior.n[i], 0.0) << name << " at " << kLambdaMinNm + i << " nm";
      EXPECT_GE(ior.k[i], 0.0) << name << " at " << kLambdaMinNm + i << " nm";
    }
  }
}

TEST(Conductors, ValuesAreTheMeasuredOnes) {
  // conductors_extra_ior.csv has CuZn rows at whole nanometres, which are grid nodes:
  // 500 nm, n = 0.686, k = 2.25; 600 nm, n = 0.45, k = 3.253.
  ConductorIor brass = conductorIor("CuZn");
  EXPECT_DOUBLE_EQ(brass.n.at(500.0), 0.686);
  EXPECT_DOUBLE_EQ(brass.k.at(500.0), 2.25);
  EXPECT_DOUBLE_EQ(brass.n.at(600.0), 0.45);
  EXPECT_DOUBLE_EQ(brass.k.at(600.0), 3.253);
  // metals_ior.csv's grid is irregular; near its 708.481 nm row gold has n = 0.161, k = 4.088.
  ConductorIor gold = conductorIor("Au");
  EXPECT_NEAR(gold.n.at(708.0), 0.161, 0.01);
  EXPECT_NEAR(gold.k.at(708.0), 4.088, 0.05);
}

TEST(Conductors, ClampBeyondTheMeasuredRange) {
  // MgO is measured to 767.68 nm only: beyond, its last values hold (not zero).
  ConductorIor mgo = conductorIor("MgO");
  EXPECT_GT(mgo.n.at(800.0), 1.5);
  EXPECT_DOUBLE_EQ(mgo.n.at(800.0), mgo.n.at(830.0));
  EXPECT_DOUBLE_EQ(mgo.k.at(800.0), mgo.k.at(830.0));
}

TEST(Conductors, UnknownNameListsTheKnownOnes) {
  try {
    conductorIor("Pt");
    ADD_FAILURE() << "no Error";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "unknown conductor 'Pt' (known: Ag, Al, Au, Cu, CuZn, MgO, TiO2)");
  }
}

}  // namespace
}  // namespace prism
