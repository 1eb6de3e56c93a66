// candump logs (proto/candump_line.hpp) replayed through the node (node/log_replay.hpp), from bytes
// no one wrote. The first byte picks the layout (classic, FD), the schedule (periodic, sync), the
// arithmetic (float, fixed point) and whether the rig's frames get a valid E2E counter and CRC
// (so the fuzzer reaches the node's computation, not only its CRC check); the rest is the log.
// - a line either parses or names what is wrong with it; a parsed line, formatted and parsed
//   again, is the same frame at the same time on the same interface;
// - the log replays deterministically: two fresh nodes transmit the same frames, bit for bit;
// - every frame the node transmits carries a valid E2E CRC and decodes to finite values, and the
//   node never counts more frames than it was given.
#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "fuzz_support.hpp"
#include "generated/tyre_mf61.hpp"
#include "generated/tyre_mf61_fixed.hpp"
#include "lut/tread_lut.hpp"
#include "node/contact_table_channel.hpp"
#include "node/contact_table_channel_fixed.hpp"
#include "node/log_replay.hpp"
#include "node/mf_tyre_channel.hpp"
#include "node/mf_tyre_channel_fixed.hpp"
#include "node/node.hpp"
#include "proto/candump_line.hpp"
#include "proto/codec.hpp"
#include "proto/e2e_profile1.hpp"

namespace {

using namespace tread;
using fuzz::fuzz_check;

struct Logged {
  proto::CanFrame frame;
  std::int64_t time_ns;
};

struct Collect {
  std::vector<proto::CanFrame>* out;
  void on_logged_tx(const proto::CanFrame& /*frame*/, std::int64_t /*time_ns*/) {}
  void on_tx(const proto::CanFrame& frame, std::int64_t /*now_ns*/) { out->push_back(frame); }
};

bool same_frame(const proto::CanFrame& a, const proto::CanFrame& b) {
  if (a.id != b.id || a.len != b.len || a.fd != b.fd || a.extended != b.extended ||
      a.error != b.error || a.bit_rate_switch != b.bit_rate_switch) {
    return false;
  }
  for (std::size_t i = 0; i < a.len; ++i) {
    if (a.data[i] != b.data[i]) return false;
  }
  return true;
}

mf::MfOptions tyre_options() {
  mf::MfOptions o = mf::options_from_use_mode(111).value;
  o.extras = true;
  return o;
}

/// One replay of `log` on a fresh node; the transmitted frames.
template <typename Tyre, typename Contact, typename Params, typename Table>
std::vector<proto::CanFrame> replay(const std::vector<Logged>& log, const node::NodeConfig& config,
                                    const Params& params, const Table& table) {
  std::array<Tyre, 4> tyres{};
  for (auto& t : tyres) t = Tyre(params, tyre_options());
  std::array<Contact, 2> contacts{};
  for (auto& c : contacts) c = Contact(table);
  node::Node<Tyre, Contact> n(config, tyres, contacts);
  std::vector<proto::CanFrame> tx;
  Collect sink{&tx};
  node::LogReplay replay(n, sink, 1'000'000);
  std::uint64_t added = 0;
  for (const Logged& l : log) {
    if (replay.add(l.frame, l.time_ns) == Status::ok) ++added;
  }
  replay.finish();
  fuzz_check(n.counters().rx_frames <= added, "the node counted frames it was not given");
  return tx;
}

void check_transmitted(const std::vector<proto::CanFrame>& tx, proto::Layout layout) {
  for (const proto::CanFrame& f : tx) {
    const proto::MessageSpec* m = proto::find_message(layout, f.id);
    fuzz_check(m != nullptr && m->direction == proto::Direction::node_to_rig && f.len == m->len,
               "the node transmitted a frame that is not one of its messages");
    fuzz_check(proto::e2e_crc(f, m->data_id()) == f.data[0], "a transmitted frame's CRC is wrong");
    proto::NodeData d;
    static_cast<void>(proto::decode(*m, f, d));
    for (const auto& w : d.wheels) {
      for (const float v : {w.fx_n, w.fy_n, w.mz_nm, w.mx_nm, w.my_nm, w.rl_m}) {
        fuzz_check(fuzz::is_finite(static_cast<double>(v)), "a transmitted wheel value not finite");
      }
    }
    for (const auto& w : d.wheelsets) {
      for (const float v :
           {w.r_left_mm, w.r_right_mm, w.delta_r_mm, w.gamma_left_rad, w.gamma_right_rad}) {
        fuzz_check(fuzz::is_finite(static_cast<double>(v)),
                   "a transmitted wheelset value not finite");
      }
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::Input input(data, size);
  const std::uint8_t pick = input.byte();
  const proto::Layout layout = (pick & 1U) != 0U ? proto::Layout::fd : proto::Layout::classic;
  const bool fixed_point = (pick & 2U) != 0U;
  const bool protect = (pick & 4U) != 0U;
  node::NodeConfig config;
  config.layout = layout;
  config.wheels = 4;
  config.wheelsets = 2;
  config.schedule = (pick & 8U) != 0U ? node::Schedule::sync : node::Schedule::periodic;

  std::string_view text = input.rest();
  std::vector<Logged> log;
  std::array<std::uint8_t, 0x800> counters{};
  while (!text.empty()) {
    const std::size_t nl = text.find('\n');
    const std::string_view line = text.substr(0, nl);
    text.remove_prefix(nl == std::string_view::npos ? text.size() : nl + 1);
    proto::CandumpLine parsed;
    const proto::CandumpError error = proto::parse_candump_line(line, parsed);
    if (error != proto::CandumpError::none) {
      fuzz_check(std::string_view(proto::describe(error)).size() > 0, "an error without words");
      continue;
    }
    std::array<char, proto::kCandumpLineMax> formatted{};
    const std::size_t len = proto::format_candump_line(parsed.frame, parsed.time_ns,
                                                       parsed.interface, formatted.data());
    proto::CandumpLine again;
    fuzz_check(proto::parse_candump_line(std::string_view(formatted.data(), len), again) ==
                       proto::CandumpError::none &&
                   same_frame(parsed.frame, again.frame) && again.time_ns == parsed.time_ns &&
                   again.interface == parsed.interface.substr(0, again.interface.size()),
               "a parsed line, formatted and parsed again, changed: " + std::string(line));
    proto::CanFrame frame = parsed.frame;
    const proto::MessageSpec* m = proto::find_message(layout, frame.id);
    if (protect && m != nullptr && m->direction == proto::Direction::rig_to_node && !frame.error &&
        !frame.extended && frame.len == m->len && frame.id < counters.size()) {
      proto::e2e_protect(
          frame, m->data_id(),
          static_cast<std::uint8_t>(counters[frame.id]++ % proto::kE2eCounterModulo));
    }
    log.push_back({frame, parsed.time_ns});
  }

  const auto run = [&] {
    if (fixed_point) {
      return replay<node::MfTyreChannelFixed, node::ContactTableChannelFixed>(
          log, config, firmware::kTyreFixed, lut::contact_pairs()[0].q);
    }
    return replay<node::MfTyreChannel, node::ContactTableChannel>(log, config, firmware::kTyre,
                                                                  lut::contact_pairs()[0].f32);
  };
  const std::vector<proto::CanFrame> first = run();
  const std::vector<proto::CanFrame> second = run();
  fuzz_check(first.size() == second.size(), "two replays sent different numbers of frames");
  for (std::size_t i = 0; i < first.size(); ++i) {
    fuzz_check(same_frame(first[i], second[i]), "two replays sent different frames");
  }
  check_transmitted(first, layout);
  return 0;
}
