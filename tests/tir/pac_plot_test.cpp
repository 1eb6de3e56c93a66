// The PAC plot script: one datablock per load plus four combined-slip blocks, each with the
// requested number of samples; gnuplot turns it into a PNG and an SVG.
#include "tir/pac_plot.hpp"
#include "plot/gnuplot.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "golden_path.hpp"
#include "test_dir.hpp"
#include "tir/pac_coefficients.hpp"

namespace {

std::filesystem::path tmp_dir() {
  // One scratch directory per test case: CTest runs the cases of this binary in parallel.
  return tread::testing::test_dir(std::string("pac_plot_test_") +
                                  ::testing::UnitTest::GetInstance()->current_test_info()->name());
}

tread::pac::PacParams<double> hmmwv() {
  const auto path = tread::testing::test_data("tyres/chrono_HMMWV_Pac89Tire.json");
  EXPECT_TRUE(std::filesystem::exists(path)) << path;
  return tread::tir::pac_from_chrono_json(path).params;
}

TEST(PacPlot, ScriptHasOneBlockPerLoadWithAllSamples) {
  tread::tir::PacPlotOptions o;
  o.loads_n = {3000.0, 5000.0};
  o.points = 11;
  const std::string script = tread::tir::pac_plot_script(hmmwv(), o, "x.png");
  std::istringstream in(script);
  std::string line;
  int blocks = 0;
  int rows = 0;
  bool inside = false;
  while (std::getline(in, line)) {
    if (line.find("<< EOD") != std::string::npos) {
      ++blocks;
      inside = true;
    } else if (line == "EOD") {
      inside = false;
    } else if (inside) {
      ++rows;
    }
  }
  EXPECT_EQ(blocks, 2 + 4);
  EXPECT_EQ(rows, 11 * (2 + 4));
  EXPECT_NE(script.find("pngcairo"), std::string::npos);
  EXPECT_THROW((void)tread::tir::pac_plot_script(hmmwv(), o, "x.jpg"), std::invalid_argument);
}

// A load above the tyre's limit is drawn at the limit (the core clamps): its legend says so, where
// it said "Fz = 10000 N" over the 6000 N curve. A load that is not a positive number is refused
// (NaN became "Fz = -2147483648 N").
TEST(PacPlot, LegendSaysWhereALoadIsDrawnAtTheLimit) {
  tread::pac::PacParams<double> p = hmmwv();
  p.fz_max_n = 6000.0;
  tread::tir::PacPlotOptions o;
  o.loads_n = {3000.0, 10000.0};
  o.points = 3;
  const std::string script = tread::tir::pac_plot_script(p, o, "x.svg");
  EXPECT_NE(script.find("'Fz = 3000 N'"), std::string::npos);
  EXPECT_NE(script.find("'Fz = 10000 N (at the load limit 6000 N)'"), std::string::npos);
  for (const double bad : {0.0, -4000.0, std::nan("")}) {
    o.loads_n = {bad};
    EXPECT_THROW((void)tread::tir::pac_plot_script(p, o, "x.svg"), std::invalid_argument) << bad;
  }
}

TEST(PacPlot, GnuplotWritesPngAndSvg) {
  for (const char* name : {"hmmwv.png", "hmmwv.svg"}) {
    const auto out = tmp_dir() / name;
    std::filesystem::remove(out);
    tread::host::run_gnuplot(tread::tir::pac_plot_script(hmmwv(), {}, out), "pac_plot_test");
    ASSERT_TRUE(std::filesystem::exists(out)) << out;
    std::ifstream f(out, std::ios::binary);
    std::string head(8, '\0');
    f.read(head.data(), 8);
    if (std::string(name).ends_with(".png")) {
      EXPECT_EQ(head.substr(1, 3), "PNG");
    } else {
      EXPECT_NE(head.find('<'), std::string::npos);
    }
    EXPECT_GT(std::filesystem::file_size(out), 10000U);
  }
}

}  // namespace
