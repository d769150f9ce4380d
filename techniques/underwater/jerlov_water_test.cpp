#include "techniques/underwater/jerlov_water.h"

#include <gtest/gtest.h>

#include "core/error.h"

namespace prism::underwater {
namespace {

TEST(JerlovWater, TenTypesAsPublishedAndSixNewerOnes) {
  std::vector<std::string> types = listJerlovTypes();
  EXPECT_EQ(types, (std::vector<std::string>{"I", "IA", "IB", "II", "III", "1C", "3C", "5C", "7C", "9C"}));
  EXPECT_EQ(listJerlovTypes(JerlovDataset::WilliamsonHollins2022),
            (std::vector<std::string>{"IB", "II", "III", "1C", "3C", "5C"}));
}

TEST(JerlovWater, ValuesAtTableNodesAndTheDocumentedExtrapolation) {
  WaterProperties clear = jerlovWater("I");
  // data/jerlov_iop_10types.csv, row "I,700,0.582,0.000685,0.653" and "I,400,0.022,0.0062,0.029".
  EXPECT_DOUBLE_EQ(clear.sigmaA.at(700.0), 0.582);
  EXPECT_DOUBLE_EQ(clear.sigmaS.at(700.0), 0.000685);
  EXPECT_DOUBLE_EQ(clear.kd.at(700.0), 0.653);
  EXPECT_DOUBLE_EQ(clear.sigmaA.at(400.0), 0.022);
  // Held at the end values beyond the table.
  EXPECT_DOUBLE_EQ(clear.sigmaA.at(780.0), 0.582);
  EXPECT_DOUBLE_EQ(clear.kd.at(830.0), 0.653);
  // Coastal water scatters far more than clear ocean.
  EXPECT_GT(jerlovWater("9C").sigmaS.at(500.0), 100.0 * clear.sigmaS.at(500.0));
  // Williamson & Hollins give extinction: a = c − b (rows "IB,400.0000,0.144,0.189,0.051" and
  // "IB,415.7895,0.141,0.184,0.045"). Their wavelengths fall between whole nanometres, so each
  // node is the table's average under the dense grid's hat (spectral/spectrum.h): at 400 nm, where
  // the table starts and is held below, its value plus a sixth of its slope.
  WaterProperties ib = jerlovWater("IB", JerlovDataset::WilliamsonHollins2022);
  const double step = 415.7895 - 400.0;
  EXPECT_NEAR(ib.sigmaA.at(400.0), (0.189 - 0.144) + ((0.184 - 0.141) - (0.189 - 0.144)) / step / 6.0, 1e-12);
  EXPECT_NEAR(ib.sigmaS.at(400.0), 0.144 + (0.141 - 0.144) / step / 6.0, 1e-12);
}

TEST(JerlovWater, UnknownNamesAreErrorsListingTheKnownOnes) {
  try {
    jerlovWater("IV");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("unknown water type \"IV\""), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("9C"), std::string::npos) << e.what();
  }
  EXPECT_THROW(jerlovWater("7C", JerlovDataset::WilliamsonHollins2022), Error);
  EXPECT_THROW(jerlovDatasetFromName("mobley"), Error);
}

}  // namespace
}  // namespace prism::underwater
