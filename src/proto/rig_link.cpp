#include "proto/rig_link.hpp"

namespace tread::proto {
namespace {

bool is_cycle_frame(const MessageSpec& m) noexcept {
  return m.id == kRigCycleId || m.id == kRigInputsFdId;
}

}  // namespace

RigLink::RigLink(Layout layout, std::uint8_t wheels, std::uint8_t wheelsets,
                 std::uint8_t wheelset_forces) noexcept
    : layout_(layout),
      wheels_(wheels > kMaxWheels ? kMaxWheels : wheels),
      wheelsets_(wheelsets > kMaxWheelsets ? kMaxWheelsets : wheelsets),
      wheelset_forces_(wheelset_forces > wheelsets_ ? wheelsets_ : wheelset_forces) {}

std::uint8_t RigLink::next_counter(std::size_t message) noexcept {
  const std::uint8_t c = counters_[message];
  counters_[message] = static_cast<std::uint8_t>((c + 1U) % kE2eCounterModulo);
  return c;
}

bool RigLink::wanted(const MessageSpec& m) const noexcept {
  if (m.direction != Direction::rig_to_node || m.id == kCommandId) {
    return false;
  }
  bool wheelset_message = false;
  bool forces_message = false;
  for (const SignalSpec& s : m.signals) {
    wheelset_message = wheelset_message || s.role == Role::ws_lateral;
    forces_message = forces_message || s.role == Role::ws_speed || s.role == Role::ws_load_left;
  }
  if (forces_message) {  // WheelsetMotion/Load per wheelset, WheelsetMotionFD for all
    return m.instance < 0 ? wheelset_forces_ > 0U : m.instance < wheelset_forces_;
  }
  if (m.instance < 0) {
    return true;  // frames for all channels (RigCycle, RigInputsFD)
  }
  return wheelset_message ? m.instance < wheelsets_ : m.instance < wheels_;
}

std::size_t RigLink::encode_cycle(const RigData& data, std::span<CanFrame> out) noexcept {
  TREAD_ASSERT(out.size() >= kMaxRigFrames);  // room for every frame: the cycle frame comes last
  const auto all = messages(layout_);
  std::size_t n = 0;
  // Channel frames first, the cycle frame last.
  for (int pass = 0; pass < 2; ++pass) {
    for (std::size_t m = 0; m < all.size() && n < out.size(); ++m) {
      if (!wanted(all[m]) || is_cycle_frame(all[m]) != (pass == 1)) {
        continue;
      }
      if (encode(all[m], data, next_counter(m), out[n]) == Status::out_of_range) {
        ++saturated_frames_;
      }
      ++n;
    }
  }
  return n;
}

CanFrame RigLink::encode_command(const Command& command) noexcept {
  RigData data{};
  data.command = command;
  const MessageSpec* m = find_message(layout_, kCommandId);
  CanFrame frame{};
  static_cast<void>(encode(*m, data, next_counter(message_index(layout_, *m)), frame));
  return frame;
}

Status RigLink::receive(const CanFrame& frame, NodeData& outputs) noexcept {
  const MessageSpec* m = find_message(layout_, frame.id);
  if (frame.error || m == nullptr || m->direction != Direction::node_to_rig) {
    return Status::invalid_argument;
  }
  if (frame.len != m->len || frame.fd != m->fd) {
    ++rejected_;
    return Status::invalid_argument;
  }
  const E2eResult r = e2e_check(frame, m->data_id(), receivers_[message_index(layout_, *m)]);
  if (!e2e_accepted(r)) {
    ++rejected_;
    return r == E2eResult::bad_crc ? Status::bad_crc : Status::bad_counter;
  }
  ++accepted_;
  return decode(*m, frame, outputs);
}

}  // namespace tread::proto
