#include "stub/stub_can_bus.hpp"

namespace tread::hal {

// ---- endpoint
// ------------------------------------------------------------------------------------
Status StubCanEndpoint::send(const proto::CanFrame& frame) noexcept {
  if (network_ == nullptr) {
    return Status::io_error;
  }
  return network_->transmit(*this, frame);
}

Status StubCanEndpoint::receive(proto::CanFrame& frame) noexcept {
  if (count_ == 0U) {
    return Status::would_block;
  }
  const proto::CanFrame& next = queue_[head_];
  if (network_ != nullptr && next.timestamp_ns > network_->now_ns()) {
    return Status::would_block;  // delayed: not due yet
  }
  frame = next;
  head_ = (head_ + 1U) % kStubQueueFrames;
  --count_;
  return Status::ok;
}

bool StubCanEndpoint::push(const proto::CanFrame& frame) noexcept {
  if (count_ == kStubQueueFrames) {
    ++rx_overflows_;
    return false;
  }
  queue_[(head_ + count_) % kStubQueueFrames] = frame;
  ++count_;
  return true;
}

// ---- network
// -------------------------------------------------------------------------------------
StubCanNetwork::StubCanNetwork(NowFn now, const void* context) noexcept
    : now_(now), context_(context) {
  for (std::size_t i = 0; i < endpoints_.size(); ++i) {
    endpoints_[i].network_ = this;
    endpoints_[i].index_ = i;
  }
}

StubCanEndpoint& StubCanNetwork::endpoint(std::size_t index) noexcept {
  TREAD_ASSERT(index < kStubEndpoints);
  return endpoints_[index < kStubEndpoints ? index : kStubEndpoints - 1U];
}

std::int64_t StubCanNetwork::now_ns() const noexcept {
  return now_ != nullptr ? now_(context_) : 0;
}

double StubCanNetwork::next_uniform() noexcept {
  // xorshift64*: deterministic, allocation-free.
  rng_ ^= rng_ >> 12U;
  rng_ ^= rng_ << 25U;
  rng_ ^= rng_ >> 27U;
  const std::uint64_t r = rng_ * 0x2545F4914F6CDD1DULL;
  return static_cast<double>(r >> 11U) * (1.0 / 9007199254740992.0);
}

Status StubCanNetwork::transmit(const StubCanEndpoint& from,
                                const proto::CanFrame& frame) noexcept {
  if (bus_off_) {
    return Status::io_error;
  }
  if (frame.len > (frame.fd ? proto::kFdMaxLen : proto::kClassicMaxLen) ||
      (frame.fd && !proto::is_valid_fd_length(frame.len))) {
    return Status::invalid_argument;
  }
  ++sent_;
  if (faults_.drop_next > 0U) {
    --faults_.drop_next;
    ++dropped_;
    return Status::ok;  // lost on the wire: the sender cannot tell
  }
  if (faults_.drop_probability > 0.0 && next_uniform() < faults_.drop_probability) {
    ++dropped_;
    return Status::ok;
  }
  proto::CanFrame wire = frame;
  if (faults_.corrupt_next > 0U && wire.len > 0U) {
    --faults_.corrupt_next;
    ++corrupted_;
    const auto bit = static_cast<std::size_t>(next_uniform() * wire.len * 8.0);
    wire.data[bit / 8U] = static_cast<std::uint8_t>(wire.data[bit / 8U] ^ (1U << (bit % 8U)));
  }
  wire.timestamp_ns = now_ns() + faults_.delay_ns;
  broadcast(&from, wire);
  return Status::ok;
}

void StubCanNetwork::broadcast(const StubCanEndpoint* from, const proto::CanFrame& frame) noexcept {
  for (StubCanEndpoint& e : endpoints_) {
    if (&e != from) {
      static_cast<void>(e.push(frame));
    }
  }
}

void StubCanNetwork::inject_error_frame(std::uint32_t error_class) noexcept {
  proto::CanFrame err{};
  err.error = true;
  err.id = error_class;
  err.len = proto::kClassicMaxLen;
  err.timestamp_ns = now_ns();
  broadcast(nullptr, err);
}

void StubCanNetwork::set_bus_off() noexcept {
  bus_off_ = true;
  inject_error_frame(kErrBusOff);
}

void StubCanNetwork::restart() noexcept {
  bus_off_ = false;
  inject_error_frame(kErrRestarted);
}

}  // namespace tread::hal
