// Cost of the wheel-rail forces per wheelset on the node's path (float, Polach): table lookup,
// two wheels' load split, creepages, creep forces, Y/Q and Nadal margin (target <= 300 ns per
// wheelset); the parts alone (Polach per contact point, Hertz scaling), and FASTSIM (host) for
// comparison. 1024 operating points over the table: tread and flange, one and two points.
#include <benchmark/benchmark.h>

#include <cstddef>
#include <vector>

#include "contact/contact_mechanics.hpp"
#include "contact/contact_setup.hpp"
#include "contact/rail_placement.hpp"
#include "node/rail_force_channel.hpp"
#include "rail/fastsim.hpp"

namespace {

using namespace tread;

struct Fixture {
  Fixture() {
    contact::ContactSetup setup;
    setup.wheel_spec = "S1002";
    setup.rail_spec = "60E1";
    const contact::RigidContact c = contact::build_contact(setup);
    const contact::ContactMaterials m;
    const auto table = contact::mechanics_table(c, -10.0, 10.0, 0.1, m);
    rows = contact::mechanics_rows_f32(table);
    node::RailForceSettings s;
    s.g_mpa = static_cast<float>(m.g_mpa());
    channel = node::RailForceTableChannel(
        rail::MechanicsTableF32{-10.0F, 0.1F, static_cast<std::uint32_t>(rows.size()), rows.data()},
        s);
    for (std::size_t i = 0; i < inputs.size(); ++i) {
      const auto u = static_cast<float>((i * 7919U) % 1024U) / 1024.0F;
      proto::WheelsetInput& in = inputs[i];
      in.lateral_mm = -9.0F + 18.0F * u;
      in.yaw_rad = 0.004F * (u - 0.5F);
      in.yaw_valid = true;
      in.speed_mps = 10.0F + 40.0F * u;
      in.lateral_velocity_mps = 0.05F * (0.5F - u);
      in.yaw_rate_radps = 0.02F * (u - 0.5F);
      in.load_left_n = 60000.0F + 30000.0F * u;
      in.load_right_n = 90000.0F - 30000.0F * u;
    }
  }
  std::vector<rail::MechanicsRowF32> rows;
  node::RailForceTableChannel channel;
  std::vector<proto::WheelsetInput> inputs = std::vector<proto::WheelsetInput>(1024);
};

const Fixture& fixture() {
  static const Fixture f;
  return f;
}

void BM_RailForcesPerWheelset(benchmark::State& state) {
  const Fixture& f = fixture();
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(f.channel.evaluate(f.inputs[i++ & 1023U]));
  }
}
BENCHMARK(BM_RailForcesPerWheelset);

rail::CreepContact<float> patch() {
  return {6.3F, 12.6F, 80000.0F, 80769.0F, rail::kalker_coefficients(0.5F, 0.3F)};
}

void BM_PolachPerContactPoint(benchmark::State& state) {
  const rail::CreepContact<float> k = patch();
  const rail::PolachParameters<float> p{};
  std::vector<rail::Creepage<float>> s(1024);
  for (std::size_t i = 0; i < s.size(); ++i) {
    const auto u = static_cast<float>((i * 7919U) % 1024U) / 1024.0F;
    s[i] = {0.004F * (u - 0.5F), 0.003F * (0.5F - u), 2e-4F * (u - 0.3F)};
  }
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(rail::polach_creep(k, s[i++ & 1023U], 30.0F, p));
  }
}
BENCHMARK(BM_PolachPerContactPoint);

void BM_FastsimPerContactPoint(benchmark::State& state) {
  const rail::CreepContact<float> k = patch();
  const rail::FastsimGrid grid{static_cast<int>(state.range(0)), static_cast<int>(state.range(0))};
  std::size_t i = 0;
  for (auto _ : state) {
    const auto u = static_cast<float>((i++ * 7919U) % 1024U) / 1024.0F;
    benchmark::DoNotOptimize(
        rail::fastsim(k, rail::Creepage<float>{0.004F * (u - 0.5F), 0.002F, 1e-4F}, 0.36F, grid));
  }
}
BENCHMARK(BM_FastsimPerContactPoint)->Arg(10)->Arg(40);

}  // namespace

BENCHMARK_MAIN();
