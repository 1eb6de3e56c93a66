// CAN frames of the protocol's messages (proto/codec.hpp, both layouts, both directions) with
// payloads no one wrote. The first bytes pick the layout and the message; the rest is the payload.
// A decoded frame, re-encoded with its own counter, carries every signal's raw value unchanged and
// a valid E2E CRC — on the fixed-point route for every signal (Q31.32 represents every raw step
// exactly), on the float route for every signal whose raw range float holds exactly (below 2^24
// steps; the 24-bit radii r are beyond it) — and decodes to finite values. Encoding a decoded
// frame twice gives the same bytes.
#include <span>
#include <string>
#include <type_traits>

#include "fixed/fixed64.hpp"
#include "fuzz_support.hpp"
#include "proto/codec.hpp"
#include "proto/e2e_profile1.hpp"
#include "proto/messages.hpp"
#include "proto/role_table.hpp"
#include "proto/signal.hpp"

namespace {

using namespace tread;
using fuzz::fuzz_check;

/// Float holds every integer below 2^24 exactly.
bool float_holds_every_step(const proto::SignalSpec& s) {
  return proto::is_integer_role(s.role) || s.length < 24U;
}

template <typename Data>
void round_trip(const proto::MessageSpec& m, const proto::CanFrame& frame, bool exact_everywhere,
                const char* route) {
  Data decoded;
  fuzz_check(proto::decode(m, frame, decoded) == Status::ok,
             std::string(route) + ": decode refused a frame of its own message");
  const std::span<const std::uint8_t> original(frame.data.data(), frame.len);
  const proto::SignalSpec* counter_signal = nullptr;
  for (const proto::SignalSpec& s : m.signals) {
    if (s.role == proto::Role::counter) counter_signal = &s;
  }
  const auto counter = static_cast<std::uint8_t>(
      counter_signal != nullptr ? proto::decode_raw_signal(*counter_signal, original) : 0);
  proto::CanFrame again;
  static_cast<void>(proto::encode(m, decoded, counter, again));
  fuzz_check(again.id == frame.id && again.len == frame.len && again.fd == frame.fd,
             std::string(route) + ": re-encoded frame has another id, length or type");
  const std::span<const std::uint8_t> bytes(again.data.data(), again.len);
  for (const proto::SignalSpec& s : m.signals) {
    if (s.role == proto::Role::crc ||
        (s.role == proto::Role::counter && counter >= proto::kE2eCounterModulo)) {
      continue;  // the CRC follows from the rest; a counter of 15 is never sent (e2e_profile1)
    }
    if (!exact_everywhere && !float_holds_every_step(s)) continue;
    fuzz_check(proto::decode_raw_signal(s, bytes) == proto::decode_raw_signal(s, original),
               std::string(route) + ": signal " + s.name + " changed its raw value on " + m.name);
  }
  fuzz_check(proto::e2e_crc(again, m.data_id()) == again.data[0],
             std::string(route) + ": re-encoded frame has a bad CRC");
  Data twice;
  static_cast<void>(proto::decode(m, again, twice));
  proto::CanFrame third;
  static_cast<void>(proto::encode(m, twice, counter, third));
  for (std::size_t i = 0; i < again.len; ++i) {
    fuzz_check(third.data[i] == again.data[i],
               std::string(route) + ": encode(decode(x)) is not stable");
  }
}

template <typename S>
void check_finite(const proto::BasicRigData<S>& d) {
  for (const auto& w : d.wheels) {
    for (const S v : {w.kappa, w.alpha_rad, w.gamma_rad, w.fz_n, w.vx_mps, w.omega_radps}) {
      if constexpr (std::is_same_v<S, float>) {
        fuzz_check(fuzz::is_finite(static_cast<double>(v)), "a decoded value not finite");
      } else {
        fuzz_check(v.valid(), "a decoded fixed-point value not valid");
      }
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::Input input(data, size);
  const std::uint8_t pick = input.byte();
  const proto::Layout layout = (pick & 0x80U) != 0U ? proto::Layout::fd : proto::Layout::classic;
  const auto all = proto::messages(layout);
  const proto::MessageSpec& m = all[(pick & 0x7FU) % all.size()];
  proto::CanFrame frame;
  frame.id = m.id;
  frame.fd = m.fd;
  frame.len = m.len;
  for (std::size_t i = 0; i < m.len; ++i) frame.data[i] = input.byte();

  if (m.direction == proto::Direction::rig_to_node) {
    round_trip<proto::RigData>(m, frame, false, "float");
    round_trip<proto::RigDataFixed>(m, frame, true, "fixed");
    proto::RigData f;
    static_cast<void>(proto::decode(m, frame, f));
    check_finite(f);
    proto::RigDataFixed q;
    static_cast<void>(proto::decode(m, frame, q));
    check_finite(q);
  } else {
    round_trip<proto::NodeData>(m, frame, false, "float");
    round_trip<proto::NodeDataFixed>(m, frame, true, "fixed");
  }
  return 0;
}
