#pragma once
// An in-process CAN bus: several endpoints, each seeing every frame the others send (like a real
// bus), with injectable faults: drop, corrupt, delay, error frames and bus-off. Fixed capacity, no
// heap: usable inside the allocation-counting tests. Time comes from a clock read through a
// function pointer so the bus works with SimClock or a real clock.

#include <array>
#include <cstddef>
#include <cstdint>

#include "core/status.hpp"
#include "hal_concepts.hpp"
#include "proto/can_frame.hpp"

namespace tread::hal {

inline constexpr std::size_t kStubEndpoints = 4;
inline constexpr std::size_t kStubQueueFrames = 512;

/// Error classes as Linux reports them in can_id of an error frame (linux/can/error.h).
enum StubErrorClass : std::uint32_t {
  kErrCtrl = 0x004U,       ///< controller problems
  kErrBusOff = 0x040U,     ///< bus off
  kErrRestarted = 0x100U,  ///< controller restarted
};

struct StubFaults {
  std::uint32_t drop_next{0};     ///< drop the next N frames sent by anyone
  std::uint32_t corrupt_next{0};  ///< flip one payload bit of the next N frames
  double drop_probability{0.0};   ///< drop each frame with this probability (deterministic PRNG)
  std::int64_t delay_ns{0};       ///< deliver frames this much later
};

class StubCanNetwork;

/// One node's view of the stub bus. Satisfies hal::CanBus.
class StubCanEndpoint {
 public:
  StubCanEndpoint() = default;
  /// @retval Status::io_error     the bus is off (bus-off injected and not restarted)
  /// @retval Status::would_block  the other endpoints' queues are full (frame counted as dropped)
  Status send(const proto::CanFrame& frame) noexcept;
  /// @retval Status::would_block  nothing due yet
  Status receive(proto::CanFrame& frame) noexcept;

  [[nodiscard]] std::uint64_t rx_overflows() const noexcept { return rx_overflows_; }
  [[nodiscard]] std::size_t queued() const noexcept { return count_; }

 private:
  friend class StubCanNetwork;
  bool push(const proto::CanFrame& frame) noexcept;

  StubCanNetwork* network_{nullptr};
  std::size_t index_{0};
  std::array<proto::CanFrame, kStubQueueFrames> queue_{};
  std::size_t head_{0};
  std::size_t count_{0};
  std::uint64_t rx_overflows_{0};
};

class StubCanNetwork {
 public:
  using NowFn = std::int64_t (*)(const void* context);

  /// `now` returns the current time for delivery scheduling (nullptr: everything is due at once).
  explicit StubCanNetwork(NowFn now = nullptr, const void* context = nullptr) noexcept;
  StubCanNetwork(const StubCanNetwork&) = delete;
  StubCanNetwork& operator=(const StubCanNetwork&) = delete;

  /// The endpoint `index` (0..kStubEndpoints-1), attached to this network.
  StubCanEndpoint& endpoint(std::size_t index) noexcept;

  StubFaults& faults() noexcept { return faults_; }
  /// Delivers an error frame of `error_class` to every endpoint.
  void inject_error_frame(std::uint32_t error_class) noexcept;
  /// Bus-off: sends fail until restart(); every endpoint receives a bus-off error frame.
  void set_bus_off() noexcept;
  void restart() noexcept;
  [[nodiscard]] bool bus_off() const noexcept { return bus_off_; }

  [[nodiscard]] std::uint64_t frames_sent() const noexcept { return sent_; }
  [[nodiscard]] std::uint64_t frames_dropped() const noexcept { return dropped_; }
  [[nodiscard]] std::uint64_t frames_corrupted() const noexcept { return corrupted_; }

 private:
  friend class StubCanEndpoint;
  Status transmit(const StubCanEndpoint& from, const proto::CanFrame& frame) noexcept;
  void broadcast(const StubCanEndpoint* from, const proto::CanFrame& frame) noexcept;
  [[nodiscard]] std::int64_t now_ns() const noexcept;
  double next_uniform() noexcept;

  std::array<StubCanEndpoint, kStubEndpoints> endpoints_{};
  NowFn now_;
  const void* context_;
  StubFaults faults_{};
  bool bus_off_{false};
  std::uint64_t rng_{0x9E3779B97F4A7C15ULL};
  std::uint64_t sent_{0};
  std::uint64_t dropped_{0};
  std::uint64_t corrupted_{0};
};

/// Adapter for StubCanNetwork's clock hook: `StubCanNetwork net(&clock_now<SimClock>, &clock);`
template <typename ClockT>
std::int64_t clock_now(const void* clock) {
  return static_cast<const ClockT*>(clock)->now_ns();
}

static_assert(CanBus<StubCanEndpoint>);

}  // namespace tread::hal
