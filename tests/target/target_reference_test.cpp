// The host end of the firmware's replay check (tests/target/CMakeLists.txt): the cortex-m4f image
// replays tests/data/target/sweep_rig.log under qemu and compares its frames with
// sweep_host_tx.log, the fixed-point cortex-m3 image with sweep_host_tx_fixed.log; the cortex
// presets cannot regenerate them (no host tools). Here: the host's replay (float, and --fixed)
// still produces exactly those files, and the host replay's node is the image's node — the same
// tyre parameters (firmware/generated/tyre_mf61.hpp in float, tyre_mf61_fixed.hpp in Q31.32, still
// what the generator makes of the .tir) and the same contact table (the flashed one, in float and
// in integers).
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>

#include "generated/tyre_mf61.hpp"
#include "generated/tyre_mf61_fixed.hpp"
#include "golden_path.hpp"
#include "lut/tread_lut.hpp"
#include "mf/mf_fixed.hpp"
#include "runtime/node_runtime.hpp"
#include "runtime/node_session.hpp"
#include "test_dir.hpp"
#include "tir/mf_header.hpp"
#include "tyre/mf_parameters_from_tir.hpp"

namespace tread {
namespace {

std::string slurp(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// `tread node --tir data/tyres/MagicFormula61_Parameters.tir --wheelsets 2
///  --wheelset-profile wheel=S1002,rail=60E1,cant=1:40` (classic CAN, periodic, 1 ms).
host::NodeSettings image_settings() {
  host::NodeSettings s;
  s.tir = testing::tyre_file("MagicFormula61_Parameters.tir");
  s.node.layout = proto::Layout::classic;
  s.node.wheels = 4;
  s.node.wheelsets = 2;
  s.node.schedule = node::Schedule::periodic;
  s.node.input_timeout_ns = 10'000'000;
  s.wheelset_profile = "wheel=S1002,rail=60E1,cant=1:40";
  return s;
}

TEST(TargetReference, HostReplayStillWritesTheCommittedTxLog) {
  const auto log = testing::test_data("target/sweep_rig.log");
  const auto expected = testing::test_data("target/sweep_host_tx.log");
  ASSERT_TRUE(std::filesystem::exists(log)) << log;
  ASSERT_TRUE(std::filesystem::exists(expected)) << expected;
  const auto out = testing::test_dir("target_reference") / "sweep_host_tx.log";
  const host::ReplayResult r = host::run_replay(image_settings(), log, 1000, out);
  EXPECT_TRUE(r.identical) << r.first_difference;
  EXPECT_EQ(r.report.loop.cycles, 250U);
  EXPECT_EQ(slurp(out), slurp(expected))
      << "the host replay changed: regenerate " << expected << " (see its README) if intended";
}

TEST(TargetReference, HostFixedReplayStillWritesTheCommittedTxLog) {
  const auto log = testing::test_data("target/sweep_rig.log");
  const auto expected = testing::test_data("target/sweep_host_tx_fixed.log");
  ASSERT_TRUE(std::filesystem::exists(expected)) << expected;
  host::NodeSettings settings = image_settings();
  settings.fixed = true;
  const auto out = testing::test_dir("target_reference") / "sweep_host_tx_fixed.log";
  const host::ReplayResult r = host::run_replay(settings, log, 1000, out);
  EXPECT_EQ(r.report.loop.cycles, 250U);
  EXPECT_EQ(r.report.counters.rx_rejected(), 0U);
  EXPECT_EQ(slurp(out), slurp(expected)) << "the host's fixed-point replay changed: regenerate "
                                         << expected << " (see its README) if intended";
}

/// The image's tyre header `path` (under the source tree) is what tread_tir_header makes of the
/// .tir today, with the header options `o` (name, scalar).
void expect_generated_tyre_header(tir::MfHeaderOptions o, const std::string& path,
                                  const std::string& flags) {
  const auto tir = testing::tyre_file("MagicFormula61_Parameters.tir");
  o.name_space = "tread::firmware";
  o.source = tir.filename().string();
  const std::string generated = tir::generate_mf_header(tyre::load_mf_parameters(tir).params, o);
  EXPECT_EQ(generated, slurp(testing::source_dir() / path))
      << "regenerate with: tread_tir_header " << tir << " " << path << " --mf"
      << (flags.empty() ? "" : " " + flags) << " --name " << o.name
      << " --namespace tread::firmware";
}

TEST(TargetReference, ImageFixedTyreHeaderIsTheGeneratorsOutput) {
  tir::MfHeaderOptions o;
  o.name = "kTyreFixed";
  o.use_fixed = true;
  expect_generated_tyre_header(o, "firmware/generated/tyre_mf61_fixed.hpp", "--fixed");
}

TEST(TargetReference, HostFixedReplayUsesTheImagesTyreAndContactTable) {
  host::NodeSettings settings = image_settings();
  settings.fixed = true;
  const host::NodeRuntime runtime(settings);
  ASSERT_TRUE(runtime.fixed());
  const mf::MfParameters<fixed::Fixed64> host = mf::to_fixed_parameters(runtime.tyre_parameters());
  const mf::MfParameters<fixed::Fixed64>& image = firmware::kTyreFixed;
  EXPECT_EQ(host.fit_type, image.fit_type);
  EXPECT_EQ(host.tyre_side, image.tyre_side);
#define TREAD_MF_CHECK(member, section, key, dflt, description) \
  EXPECT_EQ(host.member.raw(), image.member.raw()) << key;
  TREAD_MF_PARAMETER_LIST(TREAD_MF_CHECK)
#undef TREAD_MF_CHECK

  const rail::ContactTableQ& a = runtime.contact_table_q();
  const rail::ContactTableQ& b = lut::contact_pairs()[0].q;
  EXPECT_EQ(a.y_first, b.y_first);
  EXPECT_EQ(a.y_step, b.y_step);
  ASSERT_EQ(a.count, b.count);
  for (std::uint32_t i = 0; i < a.count; ++i) {
    const rail::ContactRowQ& p = a.rows[i];
    const rail::ContactRowQ& q = b.rows[i];
    EXPECT_TRUE(p.r_left == q.r_left && p.r_right == q.r_right && p.delta_r == q.delta_r &&
                p.gamma_left == q.gamma_left && p.gamma_right == q.gamma_right)
        << "row " << i;
  }
}

TEST(TargetReference, ImageTyreHeaderIsTheGeneratorsOutput) {
  tir::MfHeaderOptions o;
  o.name = "kTyre";
  o.use_float = true;
  expect_generated_tyre_header(o, "firmware/generated/tyre_mf61.hpp", "");
}

TEST(TargetReference, HostReplayUsesTheImagesTyreAndContactTable) {
  const host::NodeRuntime runtime(image_settings());
  const mf::MfParameters<float> host = mf::convert_parameters<float>(runtime.tyre_parameters());
  const mf::MfParameters<float>& image = firmware::kTyre;
  EXPECT_EQ(host.fit_type, image.fit_type);
  EXPECT_EQ(host.tyre_side, image.tyre_side);
#define TREAD_MF_CHECK(member, section, key, dflt, description)                                    \
  EXPECT_EQ(std::bit_cast<std::uint32_t>(host.member), std::bit_cast<std::uint32_t>(image.member)) \
      << key;
  TREAD_MF_PARAMETER_LIST(TREAD_MF_CHECK)
#undef TREAD_MF_CHECK

  const rail::ContactTableF32& a = runtime.contact_table();
  ASSERT_FALSE(lut::contact_pairs().empty());
  EXPECT_STREQ(lut::contact_pairs()[0].name, "wheel=S1002,rail=60E1,cant=1:40");
  const rail::ContactTableF32& b = lut::contact_pairs()[0].f32;
  EXPECT_EQ(std::bit_cast<std::uint32_t>(a.y_first_mm), std::bit_cast<std::uint32_t>(b.y_first_mm));
  EXPECT_EQ(std::bit_cast<std::uint32_t>(a.y_step_mm), std::bit_cast<std::uint32_t>(b.y_step_mm));
  ASSERT_EQ(a.count, b.count);
  const auto same = [](float x, float y) {
    return std::bit_cast<std::uint32_t>(x) == std::bit_cast<std::uint32_t>(y);
  };
  for (std::uint32_t i = 0; i < a.count; ++i) {
    const rail::ContactRowF32& p = a.rows[i];
    const rail::ContactRowF32& q = b.rows[i];
    EXPECT_TRUE(same(p.r_left_mm, q.r_left_mm) && same(p.r_right_mm, q.r_right_mm) &&
                same(p.delta_r_mm, q.delta_r_mm) && same(p.gamma_left_rad, q.gamma_left_rad) &&
                same(p.gamma_right_rad, q.gamma_right_rad))
        << "row " << i;
  }
}

}  // namespace
}  // namespace tread
