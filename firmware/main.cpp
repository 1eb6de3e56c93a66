// The firmware image's main: runs the real-time core on fixed inputs so the linker keeps it all —
// the E2E codec, the Magic Formula in float (MF 6.1, the book's default coefficients), and the
// flashed wheel–rail contact table — under the no-heap trap.
#include <array>
#include <cstdint>

#include "lut/tread_lut.hpp"
#include "mf/mf_evaluate.hpp"
#include "node/contact_table_channel.hpp"
#include "node/mf_tyre_channel.hpp"
#include "node/node.hpp"
#include "proto/rig_link.hpp"

#ifdef TREAD_HEAP_PROBE
#include "core/heap_probe.hpp"
#endif

namespace {

volatile float g_sink;  // keeps results observable
volatile std::uint32_t g_frames;

const tread::mf::MfParameters<float> kTyre{};  // MF 6.1 with the book's default coefficients

}  // namespace

int main() {
  using namespace tread;
  std::array<node::MfTyreChannel, 4> tyres{};
  for (auto& t : tyres) {
    t = node::MfTyreChannel(kTyre, mf::MfOptions{});
  }
  std::array<node::ContactTableChannel, 2> contacts{};
  for (auto& c : contacts) {
    c = node::ContactTableChannel(lut::contact_pairs()[0].f32);
  }
  const node::NodeConfig config{proto::Layout::fd,        4,    2, 10'000'000,
                                node::Schedule::periodic, true, 3};
  node::Node<node::MfTyreChannel, node::ContactTableChannel> n(config, tyres, contacts);

  proto::RigData inputs{};
  for (auto& w : inputs.wheels) {
    w = proto::WheelInput{0.05F, 0.02F, 0.0F, 4000.0F, 16.7F, 0.0F, false};
  }
  inputs.wheelsets[0].lateral_mm = 3.0F;
  proto::RigLink rig(proto::Layout::fd, 4, 2);
  std::array<proto::CanFrame, proto::RigLink::kMaxRigFrames> rx{};
  std::array<proto::CanFrame, node::kMaxTxFrames> tx{};
  const std::size_t count = rig.encode_cycle(inputs, rx);
  for (std::size_t i = 0; i < count; ++i) {
    static_cast<void>(n.receive(rx[i], 1'000'000));
  }
  g_frames = static_cast<std::uint32_t>(n.compute(1'000'000, tx));
  g_sink = n.outputs().wheels[0].fx_n + n.outputs().wheelsets[0].delta_r_mm;
#ifdef TREAD_HEAP_PROBE
  g_sink = g_sink + static_cast<float>(tread::core_heap_probe());
#endif
  return 0;
}
