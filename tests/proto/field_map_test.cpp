// FieldMap (the node's per-cycle encode and decode, fields looked up once) against the codec
// (fields looked up through the role table per frame): the same frames, values and status for
// every message of both layouts, float and fixed point, in range, saturating and not finite.
#include "proto/field_map.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <concepts>
#include <cstring>
#include <limits>
#include <random>

#include "proto/codec.hpp"
#include "proto/e2e_profile1.hpp"

namespace tread::proto {
namespace {

using fixed::Fixed64;

/// Mostly values in the signals' ranges, some far outside (saturation), some not finite.
struct Draw {
  std::mt19937_64 rng{20261126U};

  float scalar(float /*tag*/) {
    const double u = std::uniform_real_distribution<double>(-1.0, 1.0)(rng);
    switch (rng() % 8U) {
      case 0:
        return static_cast<float>(u * 1e9);
      case 1:
        return (rng() % 2U) == 0U ? std::numeric_limits<float>::quiet_NaN()
                                  : std::numeric_limits<float>::infinity();
      default:
        return static_cast<float>(u * std::pow(10.0, static_cast<double>(rng() % 5U)));
    }
  }
  Fixed64 scalar(Fixed64 /*tag*/) {
    switch (rng() % 8U) {
      case 0:
        return Fixed64::from_raw(static_cast<std::int64_t>(rng()));
      case 1:
        return Fixed64::invalid();
      default:
        return Fixed64::from_raw(static_cast<std::int64_t>(rng() % (1ULL << 46U)) - (1LL << 45U));
    }
  }
  bool flag() { return (rng() % 2U) == 0U; }
  template <typename U>
  U integer() {
    return static_cast<U>(rng());
  }
};

template <typename S>
BasicRigData<S> random_rig(Draw& d) {
  BasicRigData<S> r{};
  for (auto& w : r.wheels) {
    w = {d.scalar(S{}), d.scalar(S{}), d.scalar(S{}), d.scalar(S{}),
         d.scalar(S{}), d.scalar(S{}), d.flag()};
  }
  for (auto& ws : r.wheelsets) {
    ws = {d.scalar(S{}), d.scalar(S{}), d.flag(),      d.scalar(S{}),
          d.scalar(S{}), d.scalar(S{}), d.scalar(S{}), d.scalar(S{})};
  }
  r.rig_cycle = d.integer<std::uint32_t>();
  r.command = {d.flag(), d.flag(), d.integer<std::uint8_t>(), d.integer<std::uint8_t>()};
  return r;
}

template <typename S>
BasicNodeData<S> random_node(Draw& d) {
  BasicNodeData<S> n{};
  for (auto& w : n.wheels) {
    w.fx_n = d.scalar(S{});
    w.fy_n = d.scalar(S{});
    w.mz_nm = d.scalar(S{});
    w.mx_nm = d.scalar(S{});
    w.my_nm = d.scalar(S{});
    w.rl_m = d.scalar(S{});
    w.status = d.integer<std::uint8_t>();
  }
  for (auto& ws : n.wheelsets) {
    ws.r_left_mm = d.scalar(S{});
    ws.r_right_mm = d.scalar(S{});
    ws.delta_r_mm = d.scalar(S{});
    ws.gamma_left_rad = d.scalar(S{});
    ws.gamma_right_rad = d.scalar(S{});
    ws.status = d.integer<std::uint8_t>();
  }
  for (auto& rw : n.rail_wheels) {
    rw.fx_n = d.scalar(S{});
    rw.y_n = d.scalar(S{});
    rw.q_n = d.scalar(S{});
    rw.mz_nm = d.scalar(S{});
    rw.n1_n = d.scalar(S{});
    rw.n2_n = d.scalar(S{});
    rw.y_over_q = d.scalar(S{});
    rw.nadal_margin = d.scalar(S{});
    rw.status = d.integer<std::uint8_t>();
  }
  n.status = {d.integer<std::uint8_t>(), d.integer<std::uint16_t>(), d.integer<std::uint8_t>(),
              d.integer<std::uint8_t>(), d.integer<std::uint8_t>(),  d.integer<std::uint8_t>()};
  return n;
}

BasicRigData<float> random_data(Draw& d, const RigData* /*tag*/) {
  return random_rig<float>(d);
}
BasicNodeData<float> random_data(Draw& d, const NodeData* /*tag*/) {
  return random_node<float>(d);
}
BasicRigData<Fixed64> random_data(Draw& d, const RigDataFixed* /*tag*/) {
  return random_rig<Fixed64>(d);
}
BasicNodeData<Fixed64> random_data(Draw& d, const NodeDataFixed* /*tag*/) {
  return random_node<Fixed64>(d);
}

template <typename D>
constexpr Direction kDirection =
    std::same_as<D, RigData> || std::same_as<D, RigDataFixed> ? Direction::rig_to_node
                                                              : Direction::node_to_rig;

bool same_frame(const CanFrame& a, const CanFrame& b) {
  return a.id == b.id && a.len == b.len && a.fd == b.fd && a.bit_rate_switch == b.bit_rate_switch &&
         a.extended == b.extended && a.error == b.error && a.data == b.data;
}

template <typename D>
class FieldMapModel : public ::testing::Test {};
using Models = ::testing::Types<RigData, NodeData, RigDataFixed, NodeDataFixed>;
TYPED_TEST_SUITE(FieldMapModel, Models);

TYPED_TEST(FieldMapModel, EncodesEveryMessageAsTheCodecDoes) {
  using D = TypeParam;
  Draw draw;
  for (const Layout layout : {Layout::classic, Layout::fd}) {
    const FieldMap<D> map(layout);
    const auto all = messages(layout);
    int saturated = 0;
    for (int trial = 0; trial < 200; ++trial) {
      const D data = random_data(draw, static_cast<const D*>(nullptr));
      for (std::size_t k = 0; k < all.size(); ++k) {
        const auto counter = static_cast<std::uint8_t>(trial % kE2eCounterModulo);
        CanFrame by_codec{};
        CanFrame by_map{};
        by_map.data.fill(0xA5);  // whatever the frame held before is overwritten
        const Status want = encode(all[k], data, counter, by_codec);
        const Status got = map.encode(k, data, counter, by_map);
        ASSERT_EQ(got, want) << all[k].name << " trial " << trial;
        if (all[k].direction == kDirection<D>) {
          ASSERT_TRUE(same_frame(by_map, by_codec)) << all[k].name << " trial " << trial;
        } else {
          EXPECT_EQ(got, Status::invalid_argument);
        }
        saturated += want == Status::out_of_range ? 1 : 0;
      }
    }
    EXPECT_GT(saturated, 0);  // the draw reaches the saturating branch
    CanFrame f{};
    EXPECT_EQ(map.encode(all.size(), D{}, 0, f), Status::invalid_argument);
  }
}

TYPED_TEST(FieldMapModel, DecodesEveryMessageAsTheCodecDoes) {
  using D = TypeParam;
  Draw draw;
  for (const Layout layout : {Layout::classic, Layout::fd}) {
    const FieldMap<D> map(layout);
    const auto all = messages(layout);
    for (int trial = 0; trial < 200; ++trial) {
      const D before = random_data(draw, static_cast<const D*>(nullptr));
      for (std::size_t k = 0; k < all.size(); ++k) {
        CanFrame frame{};
        frame.id = all[k].id;
        frame.len = all[k].len;
        frame.fd = all[k].fd;
        for (auto& byte : frame.data) {
          byte = static_cast<std::uint8_t>(draw.rng());
        }
        if (trial % 10 == 9) {  // a frame of the wrong length or kind
          frame.len = static_cast<std::uint8_t>(frame.len == 8U ? 7U : 8U);
        }
        D by_codec = before;
        D by_map = before;
        const Status want = decode(all[k], frame, by_codec);
        const Status got = map.decode(k, frame, by_map);
        ASSERT_EQ(got, want) << all[k].name << " trial " << trial;
        ASSERT_EQ(std::memcmp(&by_map, &by_codec, sizeof(D)), 0)
            << all[k].name << " trial " << trial;
      }
    }
    D data{};
    EXPECT_EQ(map.decode(all.size(), CanFrame{}, data), Status::invalid_argument);
  }
}

}  // namespace
}  // namespace tread::proto
