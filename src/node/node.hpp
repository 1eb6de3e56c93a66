#pragma once
// The node's computation as a pure state machine: frames in (receive), outputs out (compute), time
// passed in as a value. No clock, no bus, no heap: the runner (hal/loop) drives it; tests drive it
// directly.
//
// Per cycle: receive() every frame drained from the bus (validate length, E2E CRC and counter; keep
// the latest sample per channel) → compute(now): per channel, stale check, clamp, model, status
// bits → encode every output frame with its own E2E counter.

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <concepts>
#include <cstdint>
#include <limits>
#include <span>

#include "node/channels.hpp"
#include "node/node_config.hpp"
#include "node/node_counters.hpp"
#include "proto/data_model.hpp"
#include "proto/e2e_profile1.hpp"
#include "proto/field_map.hpp"
#include "proto/messages.hpp"
#include "proto/role_table.hpp"
#include "proto/signal.hpp"

namespace tread::node {

/// Upper bound of output frames per cycle (classic: 4×2 wheel + 2×2 wheelset + 4×3 rail wheel +
/// status).
inline constexpr std::size_t kMaxTxFrames = 32;

/// Channel bits (wheel i: bit i, wheelset geometry j: bit 4+j, wheelset forces j: bit 6+j).
inline constexpr unsigned kWheelsetBit = 4U;
inline constexpr unsigned kForcesBit = 6U;

template <TyreChannel Tyre, ContactChannel Contact,
          RailForceChannel Forces = NoRailForce<ChannelScalar<Tyre>>>
requires std::same_as<ChannelScalar<Tyre>, ChannelScalar<Contact>> &&
    std::same_as<ChannelScalar<Tyre>, ChannelScalar<Forces>>
class Node {
 public:
  /// The physical values' scalar: float, or fixed::Fixed64 (channels on the integer-only path).
  using Scalar = ChannelScalar<Tyre>;
  using RigData = proto::BasicRigData<Scalar>;
  using NodeData = proto::BasicNodeData<Scalar>;

  /// `tyres` must hold config.wheels channels, `contacts` config.wheelsets and `forces`
  /// config.wheelset_forces; all outlive the node.
  Node(const NodeConfig& config, std::span<Tyre> tyres, std::span<Contact> contacts,
       std::span<Forces> forces = {}) noexcept
      : config_(config),
        tyres_(tyres),
        contacts_(contacts),
        forces_(forces),
        rx_fields_(config.layout),
        tx_fields_(config.layout) {
    config_.wheels = std::min<std::uint8_t>(
        {config_.wheels, proto::kMaxWheels, static_cast<std::uint8_t>(tyres.size())});
    config_.wheelsets = std::min<std::uint8_t>(
        {config_.wheelsets, proto::kMaxWheelsets, static_cast<std::uint8_t>(contacts.size())});
    config_.wheelset_forces = std::min<std::uint8_t>(
        {config_.wheelset_forces, config_.wheelsets, static_cast<std::uint8_t>(forces.size())});
    enabled_ = config_.start_enabled;
    const auto all = proto::messages(config_.layout);
    for (std::size_t m = 0; m < all.size(); ++m) {
      feeds_[m] = channel_mask(all[m]);
      receivers_[m].max_delta = config_.e2e_max_delta;
      if (all[m].direction == proto::Direction::node_to_rig && tx_count_ < kMaxTxFrames) {
        const bool is_status = all[m].id == proto::kNodeStatusId;
        const std::uint8_t configured = configured_mask();
        if (is_status || (feeds_[m] & configured) != 0U) {
          tx_list_[tx_count_++] = static_cast<std::uint8_t>(m);
        }
      }
    }
    last_valid_ns_.fill(kNever);
    for (std::size_t bit = 0; bit < 8U; ++bit) {
      for (std::size_t m = 0; m < all.size(); ++m) {
        if (all[m].direction == proto::Direction::rig_to_node &&
            ((static_cast<unsigned>(feeds_[m]) >> bit) & 1U) != 0U &&
            inputs_of_[bit].count < inputs_of_[bit].message.size()) {
          inputs_of_[bit].message[inputs_of_[bit].count++] = static_cast<std::uint8_t>(m);
        }
      }
    }
  }

  /// Validates one received frame and keeps its values.
  /// @return true when the frame is the rig's cycle frame (sync mode computes then).
  bool receive(const proto::CanFrame& frame, std::int64_t now_ns) noexcept {
    ++counters_.rx_frames;
    if (frame.error) {
      ++counters_.rx_error_frames;
      return false;
    }
    const proto::MessageSpec* m = proto::find_message(config_.layout, frame.id);
    if (m == nullptr || frame.extended || m->direction != proto::Direction::rig_to_node) {
      ++counters_.rx_ignored;
      return false;
    }
    if (frame.len != m->len || frame.fd != m->fd) {
      ++counters_.rx_bad_length;
      return false;
    }
    const std::size_t index = proto::message_index(config_.layout, *m);
    proto::E2eReceiver& rx = receivers_[index];
    const std::uint32_t lost_before = rx.lost_frames;
    const proto::E2eResult check = proto::e2e_check(frame, m->data_id(), rx);
    if (check == proto::E2eResult::bad_crc) {
      ++counters_.rx_bad_crc;
      return false;
    }
    if (!proto::e2e_accepted(check)) {
      if (check == proto::E2eResult::bad_length) {
        ++counters_.rx_bad_length;
      } else {
        ++counters_.rx_bad_counter;
      }
      return false;
    }
    counters_.lost_frames += rx.lost_frames - lost_before;
    ++counters_.rx_accepted;
    static_cast<void>(rx_fields_.decode(index, frame, latest_));
    last_valid_ns_[index] = now_ns;
    if (m->id == proto::kCommandId) {
      apply_command();
      return false;
    }
    const bool cycle_frame = m->id == proto::kRigCycleId || m->id == proto::kRigInputsFdId;
    if (cycle_frame) {
      answered_rig_cycle_ = static_cast<std::uint16_t>(latest_.rig_cycle & 0xFFFFU);
    }
    return cycle_frame;
  }

  /// Computes every channel at `now_ns` and encodes the output frames into `tx`.
  /// @return the number of frames written (at most kMaxTxFrames)
  std::size_t compute(std::int64_t now_ns, std::span<proto::CanFrame> tx) noexcept {
    ++counters_.cycles;
    const Scalar dt_s = last_compute_ns_ == kNever ? Scalar{} : seconds(now_ns - last_compute_ns_);
    last_compute_ns_ = now_ns;
    ChannelMasks masks;
    compute_wheels(now_ns, dt_s, masks);
    compute_wheelsets(now_ns, masks);
    compute_wheelset_forces(now_ns, masks);
    counters_.stale_events += static_cast<std::uint64_t>(std::popcount(masks.stale));
    counters_.clamp_events += static_cast<std::uint64_t>(std::popcount(masks.clamped));
    update_status(masks);
    return encode_outputs(tx);
  }

  /// The runner reports a missed deadline.
  void note_overrun(std::uint64_t missed = 1) noexcept { counters_.overruns += missed; }

  [[nodiscard]] const NodeCounters& counters() const noexcept { return counters_; }
  [[nodiscard]] const NodeData& outputs() const noexcept { return outputs_; }
  [[nodiscard]] const RigData& latest_inputs() const noexcept { return latest_; }
  [[nodiscard]] const NodeConfig& config() const noexcept { return config_; }
  [[nodiscard]] bool enabled() const noexcept { return enabled_; }

 private:
  static constexpr std::int64_t kNever = std::numeric_limits<std::int64_t>::min();
  using WheelOutput = proto::BasicWheelOutput<Scalar>;
  using WheelsetOutput = proto::BasicWheelsetOutput<Scalar>;
  using RailWheelOutput = proto::BasicRailWheelOutput<Scalar>;

  /// The channel bits (see kWheelsetBit, kForcesBit) that went stale or clamped this cycle.
  struct ChannelMasks {
    std::uint8_t stale{0};
    std::uint8_t clamped{0};
  };

  /// Wheels: which are due (enabled and fresh; the others zeroed with their status), their tyre
  /// channels (in one call where the channel type has it), their outputs.
  void compute_wheels(std::int64_t now_ns, Scalar dt_s, ChannelMasks& masks) noexcept {
    const std::uint8_t due = due_wheels(now_ns, masks);
    std::array<BasicTyreResult<Scalar>, proto::kMaxWheels> results{};
    if constexpr (BatchTyreChannel<Tyre>) {
      Tyre::evaluate_wheels(
          tyres_.first(config_.wheels),
          std::span<const proto::BasicWheelInput<Scalar>>(latest_.wheels).first(config_.wheels),
          due, dt_s, results);
    } else {
      for (std::size_t i = 0; i < config_.wheels; ++i) {
        if (is_due(due, i)) results[i] = tyres_[i].evaluate(latest_.wheels[i], dt_s);
      }
    }
    for (std::size_t i = 0; i < config_.wheels; ++i) {
      if (is_due(due, i)) store_wheel(i, results[i], masks);
    }
  }

  /// The wheels to compute this cycle (bit i: wheel i); the others' outputs are zero, with the
  /// disabled or stale status, and their tyres restart cleanly when they are computed again.
  std::uint8_t due_wheels(std::int64_t now_ns, ChannelMasks& masks) noexcept {
    std::uint8_t due = 0;
    for (std::size_t i = 0; i < config_.wheels; ++i) {
      const auto bit = static_cast<std::uint8_t>(1U << i);
      if (!enabled_) {
        outputs_.wheels[i] = WheelOutput{};
        outputs_.wheels[i].status = proto::kStatusDisabled;
        tyres_[i].reset();
      } else if (!fresh(bit, now_ns)) {
        outputs_.wheels[i] = WheelOutput{};
        outputs_.wheels[i].status = proto::kStatusStale;
        masks.stale = static_cast<std::uint8_t>(masks.stale | bit);
        tyres_[i].reset();
      } else {
        due = static_cast<std::uint8_t>(due | bit);
      }
    }
    return due;
  }

  void store_wheel(std::size_t i, const BasicTyreResult<Scalar>& r, ChannelMasks& masks) noexcept {
    WheelOutput& out = outputs_.wheels[i];
    out = WheelOutput{r, 0};
    if (r.clamped) {
      out.status = proto::kStatusClamped;
      masks.clamped = static_cast<std::uint8_t>(masks.clamped | (1U << i));
    }
    if (r.non_finite || !all_finite(out)) {
      zero_non_finite(out);
    }
  }

  void compute_wheelsets(std::int64_t now_ns, ChannelMasks& masks) noexcept {
    for (std::size_t j = 0; j < config_.wheelsets; ++j) {
      WheelsetOutput& out = outputs_.wheelsets[j];
      const auto bit = static_cast<std::uint8_t>(1U << (kWheelsetBit + j));
      if (!enabled_) {
        out = WheelsetOutput{};
        out.status = proto::kStatusDisabled;
        continue;
      }
      if (!fresh(bit, now_ns)) {
        out = WheelsetOutput{};
        out.status = proto::kStatusStale;
        masks.stale = static_cast<std::uint8_t>(masks.stale | bit);
        continue;
      }
      const BasicContactResult<Scalar> r = contacts_[j].evaluate(latest_.wheelsets[j]);
      out = WheelsetOutput{r, 0};
      if (r.clamped) {
        out.status = proto::kStatusClamped;
        masks.clamped = static_cast<std::uint8_t>(masks.clamped | bit);
      }
      if (!all_finite(out)) {
        zero_non_finite(out);
      }
    }
  }

  /// Per wheelset with forces: its two rail wheels (2 j: left, 2 j + 1: right).
  void compute_wheelset_forces(std::int64_t now_ns, ChannelMasks& masks) noexcept {
    for (std::size_t j = 0; j < config_.wheelset_forces; ++j) {
      const auto bit = static_cast<std::uint8_t>(1U << (kForcesBit + j));
      RailWheelOutput* out = &outputs_.rail_wheels[2U * j];
      if (!enabled_ || !fresh(bit, now_ns)) {
        const std::uint8_t status = enabled_ ? proto::kStatusStale : proto::kStatusDisabled;
        out[0] = RailWheelOutput{};
        out[1] = RailWheelOutput{};
        out[0].status = status;
        out[1].status = status;
        if (enabled_) {
          masks.stale = static_cast<std::uint8_t>(masks.stale | bit);
        }
        continue;
      }
      const BasicRailForceResult<Scalar> r = forces_[j].evaluate(latest_.wheelsets[j]);
      for (std::size_t side = 0; side < 2U; ++side) {
        store_rail_wheel(out[side], r.wheel[side], r.clamped);
      }
      if (r.clamped) {
        masks.clamped = static_cast<std::uint8_t>(masks.clamped | bit);
      }
    }
  }

  void store_rail_wheel(RailWheelOutput& out, const BasicRailWheelForces<Scalar>& forces,
                        bool clamped) noexcept {
    out = RailWheelOutput{forces, 0};
    if (clamped) {
      out.status = proto::kStatusClamped;
    }
    if (!all_finite(out)) {
      zero_non_finite(out);
    }
  }

  /// An output that did not fit: zeros, flagged out of range (keeping the status it had).
  template <typename Output>
  void zero_non_finite(Output& out) noexcept {
    ++counters_.non_finite_outputs;
    const std::uint8_t status = out.status;
    out = Output{};
    out.status = static_cast<std::uint8_t>(status | proto::kStatusOutOfRange);
  }

  void update_status(const ChannelMasks& masks) noexcept {
    proto::NodeStatusData& st = outputs_.status;
    st.state =
        static_cast<std::uint8_t>((enabled_ ? proto::kNodeEnabled : 0U) |
                                  (config_.schedule == Schedule::sync ? proto::kNodeSyncMode : 0U) |
                                  (counters_.overruns > 0U ? proto::kNodeOverrun : 0U) |
                                  (config_.layout == proto::Layout::fd ? proto::kNodeFd : 0U));
    // Sync mode: the rig cycle this answers, so that a rig in lockstep tells its answer from one of
    // the node's input-timeout computations (those repeat the last rig cycle, kNoRigCycle before
    // any), which can reach the rig while it waits for the answer to a cycle it has just sent.
    st.cycle = config_.schedule == Schedule::sync
                   ? answered_rig_cycle_
                   : static_cast<std::uint16_t>(counters_.cycles & 0xFFFFU);
    st.overruns = saturate8(counters_.overruns);
    st.rejected = saturate8(counters_.rx_rejected());
    st.stale_mask = masks.stale;
    st.clamp_mask = masks.clamped;
  }

  /// Every output message of the configured channels, each with its own E2E counter.
  std::size_t encode_outputs(std::span<proto::CanFrame> tx) noexcept {
    const auto all = proto::messages(config_.layout);
    std::size_t written = 0;
    for (std::size_t k = 0; k < tx_count_ && written < tx.size(); ++k) {
      const std::size_t m = tx_list_[k];
      if (tx_fields_.encode(m, outputs_, tx_counters_[m], tx[written]) != Status::ok) {
        ++counters_.saturated_outputs;
        mark_saturated(all[m], tx[written]);
      }
      tx_counters_[m] =
          static_cast<std::uint8_t>((tx_counters_[m] + 1U) % proto::kE2eCounterModulo);
      ++written;
    }
    counters_.tx_frames += written;
    return written;
  }

  /// Integer nanoseconds to seconds: in float without double arithmetic (soft-float on
  /// Cortex-M4F); in Q31.32 as ns·2^−32 × (2^32·10^−9), integer only.
  static Scalar seconds(std::int64_t ns) noexcept {
    if constexpr (std::same_as<Scalar, fixed::Fixed64>) {
      return fixed::Fixed64::from_raw(ns) * fixed::Fixed64(4.294967296);
    } else {
      return static_cast<float>(ns) * 1e-9F;
    }
  }
  static bool finite(float x) noexcept { return std::isfinite(x); }
  static bool finite(fixed::Fixed64 x) noexcept { return x.valid(); }

  /// The channel bits a message carries data of (see kWheelsetBit, kForcesBit). A wheelset's
  /// geometry inputs feed both of its channels, its geometry outputs the geometry channel.
  static std::uint8_t channel_mask(const proto::MessageSpec& m) noexcept {
    using proto::RoleScope;
    const bool input = m.direction == proto::Direction::rig_to_node;
    unsigned mask = 0;
    for (const proto::SignalSpec& s : m.signals) {
      const std::int8_t i = m.instance_of(s);
      if (i < 0) {
        continue;
      }
      const auto n = static_cast<unsigned>(i);
      switch (proto::role_scope(s.role)) {
        case RoleScope::wheel:
          mask |= 1U << n;
          break;
        case RoleScope::wheelset:
          mask |= (1U << (kWheelsetBit + n)) | (input ? 1U << (kForcesBit + n) : 0U);
          break;
        case RoleScope::wheelset_motion:
          mask |= 1U << (kForcesBit + n);
          break;
        case RoleScope::rail_wheel:
          mask |= 1U << (kForcesBit + n / 2U);
          break;
        default:
          break;
      }
    }
    return static_cast<std::uint8_t>(mask & 0xFFU);
  }
  [[nodiscard]] std::uint8_t configured_mask() const noexcept {
    return static_cast<std::uint8_t>(((1U << config_.wheels) - 1U) |
                                     (((1U << config_.wheelsets) - 1U) << kWheelsetBit) |
                                     (((1U << config_.wheelset_forces) - 1U) << kForcesBit));
  }
  /// Every input message feeding the channel `bit` arrived valid within the timeout.
  [[nodiscard]] bool fresh(std::uint8_t bit, std::int64_t now_ns) const noexcept {
    const ChannelInputs& inputs = inputs_of_[static_cast<std::size_t>(std::countr_zero(bit))];
    for (std::size_t k = 0; k < inputs.count; ++k) {
      const std::int64_t last = last_valid_ns_[inputs.message[k]];
      if (last == kNever || now_ns - last > config_.input_timeout_ns) {
        return false;
      }
    }
    return inputs.count > 0U;
  }
  void apply_command() noexcept {
    enabled_ = latest_.command.enable;
    if (latest_.command.reset) {
      for (std::size_t i = 0; i < config_.wheels; ++i) {
        tyres_[i].reset();
      }
      const std::uint64_t overruns = counters_.overruns;
      counters_ = NodeCounters{};
      counters_.overruns = overruns;  // a fact about the schedule, not about the session
    }
  }
  static bool all_finite(const WheelOutput& o) noexcept {
    return finite(o.fx_n) && finite(o.fy_n) && finite(o.mz_nm) && finite(o.mx_nm) &&
           finite(o.my_nm) && finite(o.rl_m);
  }
  static bool all_finite(const WheelsetOutput& o) noexcept {
    return finite(o.r_left_mm) && finite(o.r_right_mm) && finite(o.delta_r_mm) &&
           finite(o.gamma_left_rad) && finite(o.gamma_right_rad);
  }
  static bool all_finite(const RailWheelOutput& o) noexcept {
    return finite(o.fx_n) && finite(o.y_n) && finite(o.q_n) && finite(o.mz_nm) && finite(o.n1_n) &&
           finite(o.n2_n) && finite(o.y_over_q) && finite(o.nadal_margin);
  }
  static std::uint8_t saturate8(std::uint64_t v) noexcept {
    return static_cast<std::uint8_t>(v > 255U ? 255U : v);
  }
  /// Sets the saturated bit in the status signals of a frame whose encoding saturated.
  void mark_saturated(const proto::MessageSpec& m, proto::CanFrame& frame) const noexcept {
    bool changed = false;
    for (const proto::SignalSpec& s : m.signals) {
      if (s.role == proto::Role::wheel_status || s.role == proto::Role::ws_status ||
          s.role == proto::Role::rw_status) {
        const std::span<std::uint8_t> bytes(frame.data.data(), frame.len);
        const auto raw = proto::decode_raw_signal(s, bytes);
        static_cast<void>(proto::encode_raw_signal(s, raw | proto::kStatusOutOfRange, bytes));
        changed = true;
      }
    }
    if (changed) {  // re-protect with the same counter
      proto::e2e_protect(frame, m.data_id(), proto::e2e_counter_of(frame));
    }
  }

  NodeConfig config_;
  std::span<Tyre> tyres_;
  std::span<Contact> contacts_;
  std::span<Forces> forces_;
  /// Each signal's field in latest_ and outputs_, looked up once (the codec would per frame).
  proto::FieldMap<RigData> rx_fields_;
  proto::FieldMap<NodeData> tx_fields_;
  bool enabled_{true};
  /// Sync mode: the low 16 bits of the last cycle frame's RigCycle (NodeStatus.Cycle echoes it).
  std::uint16_t answered_rig_cycle_{proto::kNoRigCycle};
  RigData latest_{};
  NodeData outputs_{};
  NodeCounters counters_{};
  std::array<proto::E2eReceiver, proto::kMaxMessages> receivers_{};
  std::array<std::int64_t, proto::kMaxMessages> last_valid_ns_{};
  std::array<std::uint8_t, proto::kMaxMessages> feeds_{};
  std::array<std::uint8_t, proto::kMaxMessages> tx_counters_{};
  std::array<std::uint8_t, kMaxTxFrames> tx_list_{};
  /// Per channel bit (kWheelsetBit, kForcesBit): the input messages that feed it.
  struct ChannelInputs {
    std::array<std::uint8_t, 4> message{};
    std::size_t count{0};
  };
  std::array<ChannelInputs, 8> inputs_of_{};
  std::size_t tx_count_{0};
  std::int64_t last_compute_ns_{kNever};
};

}  // namespace tread::node
