// A link probe, not an image to run: the node on the integer-only path
// (Node<MfTyreChannelFixed, ContactTableChannelFixed>: fixed-point MF with relaxation, the integer
// contact table, the codec's Fixed64 route) linked alone with --gc-sections from `entry`, so
// scripts/check-no-softfloat.sh can show that it pulls in no soft-float routine (ctest -L target:
// target_fixed_node_has_no_softfloat). The image (main.cpp) still runs the float node.
#include "lut/tread_lut.hpp"
#include "mf/mf_options.hpp"
#include "node/contact_table_channel_fixed.hpp"
#include "node/mf_tyre_channel_fixed.hpp"
#include "node/node.hpp"

namespace {
const tread::mf::MfParameters<tread::fixed::Fixed64> g_params{};
}  // namespace

extern "C" [[noreturn]] void entry() {
  using namespace tread;
  static std::array<node::MfTyreChannelFixed, 4> tyres{};
  for (auto& t : tyres) t = node::MfTyreChannelFixed(g_params, mf::MfOptions{}, true);
  static std::array<node::ContactTableChannelFixed, 2> contacts{};
  for (auto& c : contacts) c = node::ContactTableChannelFixed(lut::contact_pairs()[0].q);
  static node::Node<node::MfTyreChannelFixed, node::ContactTableChannelFixed> n(node::NodeConfig{},
                                                                                tyres, contacts);
  static std::array<proto::CanFrame, node::kMaxTxFrames> tx{};
  volatile std::int64_t t = 0;
  for (;;) {
    static_cast<void>(n.receive(tx[0], t));
    static_cast<void>(n.compute(t, tx));
    t = t + 1000000;
  }
}
