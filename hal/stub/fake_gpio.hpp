#pragma once
// A fake output pin that records its edges with the time of a clock (fixed capacity, no heap).

#include <array>
#include <cstddef>
#include <cstdint>

#include "core/status.hpp"
#include "hal_concepts.hpp"

namespace tread::hal {

template <typename ClockT, std::size_t Capacity = 4096>
class FakeGpio {
 public:
  struct Edge {
    std::int64_t time_ns;
    bool level;
  };

  explicit FakeGpio(const ClockT& clock) noexcept : clock_(&clock) {}

  Status set(bool level) noexcept {
    if (level == level_) {
      return Status::ok;
    }
    level_ = level;
    if (count_ < Capacity) {
      edges_[count_] = Edge{clock_->now_ns(), level};
    }
    ++count_;
    return Status::ok;
  }

  [[nodiscard]] bool level() const noexcept { return level_; }
  /// Edges seen (may exceed Capacity; only the first Capacity are stored).
  [[nodiscard]] std::size_t edge_count() const noexcept { return count_; }
  [[nodiscard]] const Edge& edge(std::size_t i) const noexcept { return edges_[i]; }
  void clear() noexcept { count_ = 0; }

 private:
  const ClockT* clock_;
  std::array<Edge, Capacity> edges_{};
  std::size_t count_{0};
  bool level_{false};
};

namespace detail {
struct FakeGpioCheckClock {
  std::int64_t now_ns() const noexcept { return 0; }
  Status sleep_until_ns(std::int64_t /*deadline_ns*/) noexcept { return Status::ok; }
};
}  // namespace detail
static_assert(OutputPin<FakeGpio<detail::FakeGpioCheckClock>>);

}  // namespace tread::hal
