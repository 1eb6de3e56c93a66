// `tread node`, `tread demo` and `tread rig` refuse option values that ran forever, overflowed
// or gave NaN figures under exit 0 (an audit of the commands): each is an error naming the option.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "test_dir.hpp"

namespace {

struct CliRun {
  int status;
  std::string err;
  std::string out;
};

CliRun run(const std::string& args) {
  const auto dir =
      tread::testing::test_dir(std::string("node_cli_options_test_") +
                               ::testing::UnitTest::GetInstance()->current_test_info()->name());
  const auto err = dir / "stderr.txt";
  // A command that would run forever is stopped after 20 s (timeout's status 124).
  const std::string command = "timeout 20 " + std::string(TREAD_CLI) + " " + args + " > " +
                              (dir / "stdout.txt").string() + " 2> " + err.string();
  const int status = std::system(command.c_str());
  const auto slurp = [](const std::filesystem::path& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  };
  return {status, slurp(err), slurp(dir / "stdout.txt")};
}

std::string tir() {
  return (std::filesystem::path(TREAD_SOURCE_DIR) / "data" / "tyres" /
          "MagicFormula61_Parameters.tir")
      .string();
}

void expect_refused(const std::string& args, const std::string& what) {
  const CliRun r = run(args);
  EXPECT_NE(r.status, 0) << args;
  EXPECT_NE(r.err.find(what), std::string::npos) << args << "\n" << r.err;
}

TEST(NodeCliOptions, ValuesNoNodeTakesAreRefused) {
  const std::string node = "node --can stub --tir " + tir() + " ";
  expect_refused(node + "--timeout-ms -5",
                 "--timeout-ms: '-5': the input timeout in ms is a number");
  expect_refused(node + "--timeout-ms 1e13", "--timeout-ms: '1e13'");
  expect_refused(node + "--timeout-ms nan", "--timeout-ms: 'nan'");
  expect_refused(node + "--mu nan", "--mu: 'nan': mu0 is a number from 0.01 to 1");
  expect_refused(node + "--mu 1.5", "--mu: '1.5'");
  expect_refused(node + "--duration-s 0", "--duration-s: '0'");
  expect_refused(node + "--duration-s inf", "--duration-s: 'inf'");
  expect_refused(node + "--duration-s 1e-5", "--duration-s: 0.000010 s is shorter than one period");
  expect_refused(node + "--cycles -1", "--cycles: '-1': the cycle count is a whole number from 0");
  expect_refused(node + "--wheelsets 0 --wheelset-forces 2",
                 "--wheelset-forces: 2 wheelsets with forces, but --wheelsets 0");
  expect_refused(node + "--tx-log x.log", "--tx-log: writes the frames of a --replay");
  expect_refused(node + "--gpio-cycle-line 5", "--gpio-cycle-line: needs --gpio-chip");
  // What still runs: a duration of a few cycles.
  const CliRun ok = run(node + "--duration-s 0.01");
  EXPECT_EQ(ok.status, 0) << ok.err;
}

TEST(NodeCliOptions, ScenariosNeedAPeriodTheyCanIntegrate) {
  expect_refused("demo --clock sim --no-plot --scenario braking --period-us 20000",
                 "--period-us: 20000 us: the scenarios integrate the vehicle");
  expect_refused("demo --clock sim --no-plot --period-us 10000", "at most 5000 us");
  // The tyre test-machine sweep integrates nothing: any period.
  const CliRun sweep =
      run("demo --clock sim --no-plot --scenario sweep --sweep-duration-s 1 --period-us 20000 "
          "--out " +
          (std::filesystem::temp_directory_path() / "node_cli_options_sweep").string());
  EXPECT_EQ(sweep.status, 0) << sweep.err;
  // The demo's default of one wheelset with forces follows --wheelsets 0 down (a count the user
  // gives above --wheelsets is the error).
  const CliRun no_wheelsets = run(
      "demo --clock sim --no-plot --wheelsets 0 --scenario sweep --sweep-duration-s 0.2 --out " +
      (std::filesystem::temp_directory_path() / "node_cli_options_ws0").string());
  EXPECT_EQ(no_wheelsets.status, 0) << no_wheelsets.err;
  expect_refused("demo --clock sim --no-plot --wheelsets 1 --wheelset-forces 2 --scenario sweep",
                 "--wheelset-forces: 2 wheelsets with forces, but --wheelsets 1");
  // Real-time options on the simulated clock do nothing: said.
  const CliRun rt =
      run("demo --clock sim --no-plot --scenario sweep --sweep-duration-s 1 --cpu 1 "
          "--out " +
          (std::filesystem::temp_directory_path() / "node_cli_options_rt").string());
  EXPECT_EQ(rt.status, 0) << rt.err;
  EXPECT_NE(rt.err.find("ignored on the simulated clock"), std::string::npos) << rt.err;
}

// `tread rig` checks the node's answers against a reference built from the node's options as it is
// given them: a wheelset without its profile (it guessed S1002 on 60E1 1:40), more wheelsets with
// forces than wheelsets, or a side the node does not know, are errors before any frame is sent.
TEST(NodeCliOptions, RigRefusesAReferenceItWouldHaveToGuess) {
  const std::string rig = "rig --can vcan0 --tir " + tir() + " ";
  expect_refused(rig + "--wheelsets 1",
                 "--wheelset-profile: wheelsets need the node's wheelset profile (the reference)");
  expect_refused(rig + "--wheelsets 1 --wheelset-profile wheel=S1002,rail=60E1 --wheelset-forces 2",
                 "--wheelset-forces: 2 wheelsets with forces, but --wheelsets 1");
  expect_refused(rig + "--side up", "--side: up not in {as-measured,left,right}");
  expect_refused(rig + "--answer-timeout-ms nan", "--answer-timeout-ms: 'nan'");
  expect_refused(rig + "--sweep-duration-s nan", "--sweep-duration-s: 'nan'");
  expect_refused("demo --clock sim --no-plot --scenario sweep --sweep-duration-s nan",
                 "--sweep-duration-s: 'nan': the sweep's length in s is a number");
  expect_refused("node --can stub --tir " + tir() + " --side up",
                 "--side: up not in {as-measured,left,right}");
  // Every scenario the rig runs is in its help (curving was missing).
  const CliRun help = run("rig --help");
  EXPECT_NE(help.out.find("dynamic-hunting, curving, sweep"), std::string::npos) << help.out;
  EXPECT_NE(help.out.find("--use-mode"), std::string::npos) << help.out;
  // Without SocketCAN in the kernel (this host), the advice is what the rig can do: it has no
  // in-process bus of its own.
  const CliRun nocan = run(rig + "--scenario sweep");
  EXPECT_NE(nocan.status, 0);
  if (nocan.err.find("not available in this kernel") != std::string::npos) {
    EXPECT_NE(nocan.err.find("tread rig talks to a node process over SocketCAN only"),
              std::string::npos)
        << nocan.err;
    EXPECT_EQ(nocan.err.find("use --can stub"), std::string::npos) << nocan.err;
  }
}

// The vehicle scenarios' "tyre in double" is the node's tyre as mounted: with --side left it
// compared the node's sideslip with the as-measured (right) tyre's, 9 % apart.
TEST(NodeCliOptions, DemoReferenceTakesTheNodesSide) {
  const auto out = tread::testing::test_dir("node_cli_options_side");
  const CliRun r =
      run("demo --clock sim --no-plot --scenario step-steer --side left --out " + out.string());
  ASSERT_EQ(r.status, 0) << r.err;
  std::istringstream in(r.out);
  std::string line;
  bool seen = false;
  while (std::getline(in, line)) {
    if (line.find("sideslip_steady") == std::string::npos) continue;
    std::istringstream fields(line);
    std::string name, unit, label;
    double node = 0.0, reference = 0.0;
    fields >> name >> node >> unit >> label;  // "tyre"
    std::string in_word, double_word;
    fields >> in_word >> double_word >> reference;  // "in double:" value
    EXPECT_NEAR(node, reference, 1e-3 * std::abs(reference)) << line;
    seen = true;
  }
  EXPECT_TRUE(seen);
}

}  // namespace
