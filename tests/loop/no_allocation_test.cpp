// No heap after init: the whole loop — stub bus, rig frames, E2E, the Magic Formula in float for
// four wheels, contact channels, encoding, GPIO — runs 100 000 cycles while every operator new and
// malloc/calloc/realloc in this process is counted. The count must stay zero.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <new>
#include <vector>

#include "contact/contact_mechanics.hpp"
#include "contact/contact_setup.hpp"
#include "golden_path.hpp"
#include "loop/loop_runner.hpp"
#include "node/contact_table_channel.hpp"
#include "node/mf_tyre_channel.hpp"
#include "node/rail_force_channel.hpp"
#include "node/test_channels.hpp"
#include "proto/rig_link.hpp"
#include "rail/wheelset_model.hpp"
#include "stub/fake_gpio.hpp"
#include "stub/sim_clock.hpp"
#include "stub/stub_can_bus.hpp"
#include "tyre/mf_parameters_from_tir.hpp"

#include "allocation_counter.hpp"

using tread::testing::g_allocations;
using tread::testing::g_counting;

namespace tread {
namespace {

constexpr std::int64_t kMs = 1'000'000;

TEST(NoAllocation, TheCounterSeesNewAndMalloc) {  // the measurement itself is not vacuous
  g_allocations = 0;
  g_counting = true;
  auto* boxed = new std::array<int, 16>{};
  void* raw = std::malloc(64);
  g_counting = false;
  std::free(raw);
  delete boxed;
#if defined(__SANITIZE_ADDRESS__)
  EXPECT_GE(g_allocations.load(),
            1U);  // under ASan only operator new is counted (allocation_counter.hpp)
#else
  EXPECT_GE(g_allocations.load(), 2U);
#endif
}

TEST(NoAllocation, HundredThousandCyclesOfTheFullLoopAllocateNothing) {
  // ---- init: may allocate ----
  const auto tir = testing::tyre_file("MagicFormula61_Parameters.tir");
  const mf::MfParameters<float> params =
      mf::convert_parameters<float>(tyre::load_mf_parameters(tir).params);
  std::array<node::MfTyreChannel, 4> tyres;
  for (auto& t : tyres) {
    t = node::MfTyreChannel(params, mf::MfOptions{});
  }
  std::array<testing::LinearContact, 2> contacts{};
  const node::NodeConfig config{proto::Layout::classic,   4,    2, 10 * kMs,
                                node::Schedule::periodic, true, 3};
  node::Node<node::MfTyreChannel, testing::LinearContact> node(config, tyres, contacts);
  hal::SimClock clock(0);
  hal::StubCanNetwork net(&hal::clock_now<hal::SimClock>, &clock);
  net.faults().drop_probability = 0.001;  // exercise the lost-frame paths too
  hal::FakeGpio<hal::SimClock, 16> pin(clock);
  hal::NoObserver observer;
  hal::LoopRunner loop(node, net.endpoint(0), clock, pin, hal::LoopConfig{}, observer);
  proto::RigLink rig(proto::Layout::classic, 4, 2);
  std::array<proto::CanFrame, proto::RigLink::kMaxRigFrames> frames{};
  proto::NodeData outputs{};
  proto::RigData inputs{};

  // ---- the measured region ----
  g_allocations = 0;
  g_counting = true;
  constexpr std::uint32_t kCycles = 100'000;
  for (std::uint32_t c = 0; c < kCycles; ++c) {
    const float phase = static_cast<float>(c % 2000) / 2000.0F;
    for (std::size_t i = 0; i < 4; ++i) {
      inputs.wheels[i] = proto::WheelInput{0.3F * phase - 0.15F,
                                           0.2F * phase - 0.1F,
                                           0.02F,
                                           2000.0F + 4000.0F * phase,
                                           16.7F,
                                           0.0F,
                                           false};
    }
    inputs.wheelsets[0].lateral_mm = 20.0F * phase - 10.0F;
    inputs.rig_cycle = c;
    const std::size_t n = rig.encode_cycle(inputs, frames);
    for (std::size_t k = 0; k < n; ++k) {
      static_cast<void>(net.endpoint(1).send(frames[k]));
    }
    loop.run_periodic_cycle();
    proto::CanFrame f{};
    while (net.endpoint(1).receive(f) == Status::ok) {
      static_cast<void>(rig.receive(f, outputs));
    }
  }
  g_counting = false;

  EXPECT_EQ(g_allocations.load(), 0U);
  EXPECT_EQ(loop.stats().cycles, kCycles);
  EXPECT_GT(node.counters().lost_frames, 0U);
  EXPECT_EQ(node.counters().non_finite_outputs, 0U);
  EXPECT_GT(rig.accepted(), 13U * kCycles * 99U / 100U);
  EXPECT_NE(outputs.wheels[0].fx_n, 0.0F);
}

TEST(NoAllocation, WheelRailForcesInTheLoopAllocateNothing) {
  // ---- init: the contact and mechanics tables of S1002 on 60E1 (may allocate) ----
  contact::ContactSetup setup;
  setup.wheel_spec = "S1002";
  setup.rail_spec = "60E1";
  const contact::RigidContact c = contact::build_contact(setup);
  const contact::ContactTable t = c.table(-10.0, 10.0, 0.1);
  std::vector<rail::ContactRowF32> rows(t.y_mm.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    rows[i] = {static_cast<float>(t.r_left_mm[i]), static_cast<float>(t.r_right_mm[i]),
               static_cast<float>(t.delta_r_mm[i]), static_cast<float>(t.gamma_left_rad[i]),
               static_cast<float>(t.gamma_right_rad[i])};
  }
  const rail::ContactTableF32 table{-10.0F, 0.1F, static_cast<std::uint32_t>(rows.size()),
                                    rows.data()};
  const std::vector<rail::MechanicsRowF32> mech =
      contact::mechanics_rows_f32(contact::mechanics_table(c, -10.0, 10.0, 0.1, {}));
  const rail::MechanicsTableF32 mech_table{-10.0F, 0.1F, static_cast<std::uint32_t>(mech.size()),
                                           mech.data()};
  std::array<node::NoTyre, 1> tyres{};
  std::array<node::ContactTableChannel, 2> contacts{node::ContactTableChannel(table),
                                                    node::ContactTableChannel(table)};
  std::array<node::RailForceTableChannel, 2> forces{
      node::RailForceTableChannel(mech_table, node::RailForceSettings{}),
      node::RailForceTableChannel(mech_table, node::RailForceSettings{})};
  node::NodeConfig config{proto::Layout::classic,   0,    2, 10 * kMs,
                          node::Schedule::periodic, true, 3};
  config.wheelset_forces = 2;
  node::Node<node::NoTyre, node::ContactTableChannel, node::RailForceTableChannel> node(
      config, tyres, contacts, forces);
  hal::SimClock clock(0);
  hal::StubCanNetwork net(&hal::clock_now<hal::SimClock>, &clock);
  hal::FakeGpio<hal::SimClock, 16> pin(clock);
  hal::NoObserver observer;
  hal::LoopRunner loop(node, net.endpoint(0), clock, pin, hal::LoopConfig{}, observer);
  proto::RigLink rig(proto::Layout::classic, 0, 2, 2);
  std::array<proto::CanFrame, proto::RigLink::kMaxRigFrames> frames{};
  proto::NodeData outputs{};
  proto::RigData inputs{};

  // ---- the measured region: a slow sweep over tread and flange, yawed, both wheelsets ----
  g_allocations = 0;
  g_counting = true;
  constexpr std::uint32_t kCycles = 100'000;
  float worst_y_over_q = 0.0F;
  for (std::uint32_t c_i = 0; c_i < kCycles; ++c_i) {
    const float phase = static_cast<float>(c_i % 4000) / 4000.0F;
    for (std::size_t j = 0; j < 2; ++j) {
      proto::WheelsetInput& w = inputs.wheelsets[j];
      w.lateral_mm = (j == 0 ? 1.0F : -1.0F) * (18.0F * phase - 9.0F);
      w.yaw_rad = 0.004F * (phase - 0.5F);
      w.yaw_valid = true;
      w.speed_mps = 30.0F;
      w.lateral_velocity_mps = 0.02F;
      w.yaw_rate_radps = 0.01F;
      w.load_left_n = 80000.0F;
      w.load_right_n = 75000.0F;
    }
    inputs.rig_cycle = c_i;
    const std::size_t n = rig.encode_cycle(inputs, frames);
    for (std::size_t k = 0; k < n; ++k) {
      static_cast<void>(net.endpoint(1).send(frames[k]));
    }
    loop.run_periodic_cycle();
    proto::CanFrame f{};
    while (net.endpoint(1).receive(f) == Status::ok) {
      static_cast<void>(rig.receive(f, outputs));
    }
    worst_y_over_q = std::max(worst_y_over_q, outputs.rail_wheels[0].y_over_q);
  }
  g_counting = false;

  EXPECT_EQ(g_allocations.load(), 0U);
  EXPECT_EQ(node.counters().non_finite_outputs, 0U);
  EXPECT_GT(worst_y_over_q, 1.0F);  // the sweep reached the flange
  EXPECT_NE(outputs.rail_wheels[3].q_n, 0.0F);
}

#if !defined(NDEBUG) && defined(EIGEN_RUNTIME_NO_MALLOC)
TEST(NoAllocationDeathTest, EigenHeapForbiddenCatchesADynamicMatrix) {
  // The guard the wheelset model holds is not vacuous: a dynamic matrix inside it aborts a debug
  // build; outside it the heap is allowed again (the fitter's Ceres code needs it).
  EXPECT_DEATH(
      {
        const rail::EigenHeapForbidden no_heap;
        Eigen::MatrixXd m(8, 8);
        m.setZero();
      },
      "heap allocation is forbidden");
  Eigen::MatrixXd allowed(8, 8);
  allowed.setOnes();
  EXPECT_EQ(allowed.sum(), 64.0);
}
#endif

TEST(NoAllocation, WheelsetModelAndItsEigenAnalysisAllocateNothing) {
  // The rig's wheelset step (4x4 linearly implicit solve) and the linear analysis (system matrix,
  // eigenvalues of a fixed-size 4x4): fixed-size Eigen, no heap, counted in any build (debug
  // builds also assert inside rail::EigenHeapForbidden scopes).
  const rail::WheelsetParams<double> p;
  rail::Matrix2<double> k;
  k << -1.4e5, 1.9e7, -3.5e6, -6.2e4;
  rail::Matrix2<double> d;
  d << -6.3e5, -1.9e3, 2.0e3, -3.6e5;
  const Eigen::Matrix4d j = rail::system_matrix(p, k, d);
  rail::WheelsetState<double> s;
  s.q(0) = 1e-3;
  g_allocations = 0;
  g_counting = true;
  double growth = 0.0;
  for (int n = 0; n < 100'000; ++n) {
    const rail::Vector2<double> f = k * s.q + d * s.v;
    rail::wheelset_step(s, f, j, p, 1e-3);
    if (n % 1000 == 0) {
      const rail::EigenHeapForbidden no_heap;
      const Eigen::EigenSolver<Eigen::Matrix4d> solver(rail::system_matrix(p, k, d), false);
      growth = std::max(growth, solver.eigenvalues().real().maxCoeff());
    }
  }
  g_counting = false;
  EXPECT_EQ(g_allocations.load(), 0U);
  EXPECT_TRUE(std::isfinite(s.q(0)) && std::isfinite(growth));
}

}  // namespace
}  // namespace tread
