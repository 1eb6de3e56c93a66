// The node serving wheel-rail forces: the rig's WheelsetIn, WheelsetMotion and WheelsetLoad in,
// RailWheelForce/Contact/Derail (classic) or RailWheelsOutFD out, the numbers equal to the host's
// double-precision evaluation of the same contact within the signals' quantisation; stale when
// the force inputs stop while the geometry goes on; nothing non-finite on wild inputs.
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "contact/contact_mechanics.hpp"
#include "contact/contact_setup.hpp"
#include "proto/rig_link.hpp"
#include "runtime/node_runtime.hpp"

namespace tread {
namespace {

constexpr std::int64_t kMs = 1'000'000;
constexpr const char* kStandard = "wheel=S1002,rail=60E1,cant=1:40";
// Metre gauge: e0 = 925/2 + 70 = 532.5 mm, not the standard wheelset's 750 mm.
constexpr const char* kMetre = "wheel=S1002,rail=60E1,cant=1:40,gauge=1000,b2b=925";

host::NodeSettings settings(proto::Layout layout, const char* spec) {
  host::NodeSettings s;
  s.node.layout = layout;
  s.node.wheels = 0;
  s.node.wheelsets = 2;
  s.node.wheelset_forces = 2;
  s.wheelset_profile = spec;
  s.wheelset_ymax_mm = 10.0;
  return s;
}

proto::WheelsetInput motion(float y_mm, float yaw, float v, float q_left, float q_right) {
  proto::WheelsetInput in;
  in.lateral_mm = y_mm;
  in.yaw_rad = yaw;
  in.yaw_valid = true;
  in.speed_mps = v;
  in.load_left_n = q_left;
  in.load_right_n = q_right;
  return in;
}

struct NodeRun {
  explicit NodeRun(proto::Layout layout, std::uint8_t forces_sent = 2, const char* spec = kStandard)
      : runtime(settings(layout, spec)), rig(layout, 0, 2, forces_sent) {}

  proto::NodeData cycle(std::int64_t now_ns, const proto::RigData& data) {
    std::array<proto::CanFrame, proto::RigLink::kMaxRigFrames> frames{};
    const std::size_t n = rig.encode_cycle(data, frames);
    proto::NodeData out{};
    runtime.visit([&](auto& node) {
      for (std::size_t k = 0; k < n; ++k) {
        static_cast<void>(node.receive(frames[k], now_ns));
      }
      std::array<proto::CanFrame, node::kMaxTxFrames> tx{};
      tx_count = node.compute(now_ns, tx);
      for (std::size_t k = 0; k < tx_count; ++k) {
        EXPECT_EQ(rig.receive(tx[k], out), Status::ok) << tx[k].id;
      }
    });
    return out;
  }

  host::NodeRuntime runtime;
  proto::RigLink rig;
  std::size_t tx_count = 0;
};

/// The host's double evaluation of the same wheelset state (sim/contact), with the wheelset's own
/// e0 (b2b/2 + 70 mm) and the profiles' flange angle (not the steepest within the table's 10 mm).
rail::WheelForces<double> reference(bool right, const proto::WheelsetInput& in,
                                    const char* spec = kStandard) {
  const contact::ContactSetup setup = host::parse_wheelset_profile(spec);
  const contact::RigidContact c = contact::build_contact(setup);
  const contact::ContactMaterials m;
  const contact::MechanicsRow row = contact::mechanics_row(c.at(in.lateral_mm), m);
  const contact::FlangeAngles flange = contact::profile_flange_angles(c, 10.0);
  contact::WheelsetState state;
  state.speed_m_s = in.speed_mps;
  state.yaw_rad = in.yaw_rad;
  state.lateral_velocity_m_s = in.lateral_velocity_mps;
  state.yaw_rate_rad_s = in.yaw_rate_radps;
  state.load_left_n = in.load_left_n;
  state.load_right_n = in.load_right_n;
  // The node's axle spins at V / r with r the mean rolling radius at y = 0.
  const double r_spin = 0.5 * (c.at(0.0).left.r_mm + c.at(0.0).right.r_mm);
  return contact::evaluate_wheel(right ? row.right : row.left, right, state, r_spin,
                                 contact::half_contact_base_mm(setup), m,
                                 right ? flange.right_rad : flange.left_rad,
                                 contact::friction_parameters("kalker"), contact::CreepLaw::polach);
}

class RailForceNode : public ::testing::TestWithParam<proto::Layout> {};

void expect_the_hosts_forces(proto::Layout layout, const char* spec) {
  NodeRun run(layout, 2, spec);
  // Table rows are every 0.1 mm: pick y on a row so interpolation adds nothing.
  for (const float y : {-6.0F, -2.0F, 0.0F, 1.5F, 4.0F, 7.0F}) {
    proto::RigData d;
    d.wheelsets[0] = motion(y, 0.002F, 30.0F, 80000.0F, 76000.0F);
    d.wheelsets[1] = motion(-y, -0.001F, 30.0F, 70000.0F, 72000.0F);
    // A yaw rate makes e0 count: the longitudinal creepage holds e0 psi' / V.
    d.wheelsets[0].yaw_rate_radps = 0.02F;
    d.wheelsets[0].lateral_velocity_mps = 0.01F;
    d.wheelsets[1].yaw_rate_radps = -0.015F;
    proto::NodeData out{};
    for (int c = 1; c <= 3; ++c) {
      out = run.cycle(c * kMs, d);
    }
    EXPECT_EQ(run.tx_count, layout == proto::Layout::classic ? 17U : 4U);
    for (std::size_t j = 0; j < 2; ++j) {
      for (std::size_t side = 0; side < 2; ++side) {
        const proto::RailWheelOutput& o = out.rail_wheels[2 * j + side];
        const rail::WheelForces<double> r = reference(side == 1, d.wheelsets[j], spec);
        const double q = side == 0 ? d.wheelsets[j].load_left_n : d.wheelsets[j].load_right_n;
        const double tol = 2e-3 * q + 8.0;  // float vs double, and the 8 N signal step
        EXPECT_EQ(o.status, 0U) << "y " << y << " wheelset " << j << " side " << side;
        EXPECT_NEAR(o.n1_n, r.point[0].normal_n, tol) << y;
        EXPECT_NEAR(o.n2_n, r.point[1].normal_n, tol) << y;
        EXPECT_NEAR(o.fx_n, r.point[0].creep.fx_n + r.point[1].creep.fx_n, tol) << y;
        EXPECT_NEAR(o.y_n, r.yq.y_n, tol) << y;
        EXPECT_NEAR(o.q_n, r.yq.q_n, tol) << y;
        EXPECT_NEAR(o.mz_nm, (r.point[0].creep.mz_nmm + r.point[1].creep.mz_nmm) * 1e-3,
                    0.05 + 2e-3 * std::abs(r.point[0].creep.mz_nmm * 1e-3))
            << y;
        EXPECT_NEAR(o.y_over_q, r.derailment.y_over_q, 2e-3) << y;
        EXPECT_NEAR(o.nadal_margin, r.derailment.margin, 2e-3) << y;
      }
    }
  }
}

TEST_P(RailForceNode, ServesTheHostsForcesWithinTheSignalSteps) {
  expect_the_hosts_forces(GetParam(), kStandard);
}

// The creepages take the wheelset's own e0 (a yawed, lateral-moving metre-gauge axle).
TEST_P(RailForceNode, MetreGaugeWheelsetUsesItsOwnContactBase) {
  expect_the_hosts_forces(GetParam(), kMetre);
}

TEST_P(RailForceNode, ForcesGoStaleWithoutTheirInputsWhileTheGeometryGoesOn) {
  NodeRun run(GetParam(), 0);  // the rig sends no WheelsetMotion / WheelsetLoad
  proto::RigData d;
  d.wheelsets[0] = motion(2.0F, 0.0F, 30.0F, 80000.0F, 80000.0F);
  d.wheelsets[1] = d.wheelsets[0];
  const proto::NodeData out = run.cycle(1 * kMs, d);
  EXPECT_EQ(out.wheelsets[0].status, 0U);
  EXPECT_GT(out.wheelsets[0].r_left_mm, 400.0F);
  for (const proto::RailWheelOutput& w : out.rail_wheels) {
    EXPECT_EQ(w.status, proto::kStatusStale);
    EXPECT_EQ(w.y_n, 0.0F);
  }
  const std::uint8_t stale = out.status.stale_mask;
  EXPECT_EQ(stale, 0xC0U);  // bits 6 and 7: both wheelsets' forces
}

TEST_P(RailForceNode, WildInputsGiveFiniteOrFlaggedOutputs) {
  NodeRun run(GetParam());
  proto::RigData d;
  // Outside the table, standing, a lifted wheel, the largest encodable values.
  d.wheelsets[0] = motion(30.0F, 0.3F, 0.0F, 0.0F, 250000.0F);
  d.wheelsets[1] = motion(-30.0F, -0.3F, 600.0F, 250000.0F, 1.0F);
  d.wheelsets[1].lateral_velocity_mps = 3.0F;
  d.wheelsets[1].yaw_rate_radps = -3.0F;
  const proto::NodeData out = run.cycle(1 * kMs, d);
  for (const proto::RailWheelOutput& w : out.rail_wheels) {
    EXPECT_TRUE(std::isfinite(w.fx_n) && std::isfinite(w.y_n) && std::isfinite(w.q_n) &&
                std::isfinite(w.y_over_q) && std::isfinite(w.nadal_margin));
    EXPECT_NE(w.status & proto::kStatusClamped, 0U);  // y beyond the table's 10 mm
  }
  // The lifted wheel: no load, no quotient, the margin is the whole limit.
  EXPECT_EQ(out.rail_wheels[0].n1_n, 0.0F);
  EXPECT_EQ(out.rail_wheels[0].y_over_q, 0.0F);
  EXPECT_GT(out.rail_wheels[0].nadal_margin, 1.0F);
  EXPECT_EQ(run.runtime.counters().non_finite_outputs, 0U);
}

INSTANTIATE_TEST_SUITE_P(Layouts, RailForceNode,
                         ::testing::Values(proto::Layout::classic, proto::Layout::fd));

}  // namespace
}  // namespace tread
