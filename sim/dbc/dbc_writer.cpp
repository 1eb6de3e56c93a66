#include "dbc/dbc_writer.hpp"

#include <charconv>
#include <sstream>

namespace tread::host {
namespace {

// Shortest decimal that round-trips: "5e-05", "0.01", "1".
std::string number(double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  return std::string(buffer, result.ptr);
}

const char* role_comment(proto::Role role) {
  using proto::Role;
  switch (role) {
    case Role::crc:
      return "E2E CRC-8/SAE-J1850 over data ID (low, high byte) and bytes 1..n-1";
    case Role::counter:
      return "E2E alive counter 0..14";
    case Role::kappa:
      return "longitudinal slip ratio";
    case Role::alpha:
      return "slip angle (ISO-W)";
    case Role::gamma:
      return "inclination (camber) angle";
    case Role::fz:
      return "vertical load";
    case Role::vx:
      return "longitudinal speed of the wheel centre";
    case Role::omega:
      return "wheel spin rate (valid if OmegaValid)";
    case Role::omega_valid:
      return "1: Omega carries a value";
    case Role::ws_lateral:
      return "wheelset lateral displacement, + toward the left rail";
    case Role::ws_yaw:
      return "wheelset yaw angle (valid if YawValid)";
    case Role::ws_yaw_valid:
      return "1: Yaw carries a value";
    case Role::rig_cycle:
      return "rig cycle number; in sync mode the node computes when this arrives";
    case Role::cmd_enable:
      return "1: node computes and sends outputs";
    case Role::cmd_reset:
      return "1: reset transient states and counters";
    case Role::cmd_tyre_set:
      return "tyre parameter set to use";
    case Role::cmd_profile_set:
      return "wheel/rail profile set to use";
    case Role::fx:
      return "longitudinal force (ISO-W)";
    case Role::fy:
      return "lateral force (ISO-W)";
    case Role::mz:
      return "self-aligning moment";
    case Role::mx:
      return "overturning moment";
    case Role::my:
      return "rolling resistance moment";
    case Role::rl:
      return "loaded radius";
    case Role::wheel_status:
      return "bit0 stale, bit1 input clamped, bit2 disabled, bit3 output saturated";
    case Role::r_left:
      return "rolling radius of the left wheel at its contact point";
    case Role::r_right:
      return "rolling radius of the right wheel at its contact point";
    case Role::delta_r:
      return "rolling radius difference r_left - r_right";
    case Role::gamma_left:
      return "contact angle, left wheel";
    case Role::gamma_right:
      return "contact angle, right wheel";
    case Role::ws_status:
      return "bit0 stale, bit1 input clamped (outside table), bit2 disabled, bit3 saturated";
    case Role::node_state:
      return "bit0 enabled, bit1 sync mode, bit2 overrun seen, bit3 FD layout";
    case Role::node_cycle:
      return "node cycle number (wraps)";
    case Role::node_overruns:
      return "missed deadlines since start (saturating)";
    case Role::node_rejected:
      return "rejected frames since start (saturating)";
    case Role::node_stale_mask:
      return "bit i: wheel i stale, bit 4+j: wheelset j stale, bit 6+j: its forces stale";
    case Role::node_clamp_mask:
      return "bit i: wheel i clamped, bit 4+j: wheelset j clamped, bit 6+j: its forces clamped";
    case Role::ws_speed:
      return "wheelset forward speed";
    case Role::ws_lateral_velocity:
      return "wheelset lateral velocity, + toward the left rail";
    case Role::ws_yaw_rate:
      return "wheelset yaw rate, counter-clockwise seen from above";
    case Role::ws_load_left:
      return "vertical wheel load, left wheel";
    case Role::ws_load_right:
      return "vertical wheel load, right wheel";
    case Role::rw_fx:
      return "longitudinal creep force on the wheel (sum of its contact points)";
    case Role::rw_y:
      return "lateral force of the rail on the wheel, + toward the track centre";
    case Role::rw_q:
      return "vertical force of the rail on the wheel";
    case Role::rw_mz:
      return "spin moment about the contact normal (wheel frame, y toward its field side)";
    case Role::rw_n1:
      return "normal force at the main contact point";
    case Role::rw_n2:
      return "normal force at the second contact point (two-point contact), else 0";
    case Role::rw_y_over_q:
      return "derailment quotient Y/Q (0 when the wheel has lifted)";
    case Role::rw_nadal_margin:
      return "Nadal's limit minus Y/Q (> 0: below the limit)";
    case Role::rw_status:
      return "bit0 stale, bit1 input clamped (outside table), bit2 disabled, bit3 saturated";
  }
  return "";
}

}  // namespace

std::string signal_name(const proto::SignalSpec& signal) {
  std::string name = signal.name;
  if (signal.instance >= 0) {
    name += "_" + std::to_string(signal.instance);
  }
  return name;
}

std::string message_name(const proto::MessageSpec& message) {
  std::string name = message.name;
  if (message.instance >= 0) {
    name += "_" + std::to_string(message.instance);
  }
  return name;
}

std::string write_dbc(proto::Layout layout) {
  const bool fd = layout == proto::Layout::fd;
  std::ostringstream out;
  out << "VERSION \"tread " << (fd ? "CAN FD" : "classic CAN") << " layout 1\"\n\n";
  out << "NS_ :\n    CM_\n    BA_DEF_\n    BA_\n    BA_DEF_DEF_\n\n";
  out << "BS_:\n\n";
  out << "BU_: Rig Node\n\n";
  for (const proto::MessageSpec& m : proto::messages(layout)) {
    const bool to_node = m.direction == proto::Direction::rig_to_node;
    out << "BO_ " << m.id << ' ' << message_name(m) << ": " << static_cast<int>(m.len) << ' '
        << (to_node ? "Rig" : "Node") << '\n';
    for (const proto::SignalSpec& s : m.signals) {
      out << " SG_ " << signal_name(s) << " : " << s.start_bit << '|' << static_cast<int>(s.length)
          << "@1" << (s.is_signed ? '-' : '+') << " (" << number(s.factor) << ','
          << number(s.offset) << ") [" << number(s.physical_min()) << '|'
          << number(s.physical_max()) << "] \"" << s.unit << "\" " << (to_node ? "Node" : "Rig")
          << '\n';
    }
    out << '\n';
  }
  out << "CM_ \"tread node protocol, " << (fd ? "CAN FD" : "classic CAN")
      << " layout. Generated by 'tread proto dbc' from src/proto/messages.cpp; do not edit.\";\n";
  for (const proto::MessageSpec& m : proto::messages(layout)) {
    for (const proto::SignalSpec& s : m.signals) {
      out << "CM_ SG_ " << m.id << ' ' << signal_name(s) << " \"" << role_comment(s.role)
          << "\";\n";
    }
  }
  out << "BA_DEF_ BO_ \"VFrameFormat\" ENUM \"StandardCAN\",\"ExtendedCAN\",\"reserved\","
         "\"reserved\",\"reserved\",\"reserved\",\"reserved\",\"reserved\",\"reserved\","
         "\"reserved\",\"reserved\",\"reserved\",\"reserved\",\"reserved\",\"StandardCAN_FD\","
         "\"ExtendedCAN_FD\";\n";
  out << "BA_DEF_ \"BusType\" STRING ;\n";
  out << "BA_DEF_DEF_ \"VFrameFormat\" \"StandardCAN\";\n";
  out << "BA_DEF_DEF_ \"BusType\" \"CAN\";\n";
  out << "BA_ \"BusType\" \"" << (fd ? "CAN FD" : "CAN") << "\";\n";
  for (const proto::MessageSpec& m : proto::messages(layout)) {
    if (m.fd) {
      out << "BA_ \"VFrameFormat\" BO_ " << m.id << " 14;\n";
    }
  }
  return out.str();
}

}  // namespace tread::host
