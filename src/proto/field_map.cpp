#include "proto/field_map.hpp"

#include <concepts>
#include <cstring>
#include <type_traits>

#include "proto/codec_detail.hpp"
#include "proto/e2e_profile1.hpp"

namespace tread::proto {
namespace {

using detail::ScalarOf;

template <typename D>
constexpr Direction kDirectionOf =
    std::same_as<D, BasicRigData<ScalarOf<D>>> ? Direction::rig_to_node : Direction::node_to_rig;

template <typename Field, typename S>
constexpr FieldType field_type() noexcept {
  if constexpr (std::same_as<Field, S>) {
    return FieldType::scalar;
  } else if constexpr (std::same_as<Field, bool>) {
    return FieldType::flag;
  } else if constexpr (std::same_as<Field, std::uint8_t>) {
    return FieldType::u8;
  } else if constexpr (std::same_as<Field, std::uint16_t>) {
    return FieldType::u16;
  } else {
    static_assert(std::same_as<Field, std::uint32_t>, "a field type FieldType does not name");
    return FieldType::u32;
  }
}

template <typename T>
T load(const std::byte* at) noexcept {
  T v;
  std::memcpy(&v, at, sizeof v);
  return v;
}
template <typename T>
void store(std::byte* at, T v) noexcept {
  std::memcpy(at, &v, sizeof v);
}

}  // namespace

template <typename D>
FieldMap<D>::FieldMap(Layout layout) noexcept : messages_(messages(layout)) {
  static_assert(std::is_trivially_copyable_v<D>, "fields are moved as bytes");
  static constexpr D kProbe{};
  const auto* base = reinterpret_cast<const std::byte*>(&kProbe);
  std::size_t next = 0;
  for (std::size_t k = 0; k < messages_.size(); ++k) {
    const MessageSpec& m = messages_[k];
    first_[k] = static_cast<std::uint16_t>(next);
    for (const SignalSpec& s : m.signals) {
      FieldSlot slot{};
      if (s.role != Role::crc && s.role != Role::counter) {
        detail::with_field(kProbe, m, s, [&](const auto& field) {
          using Field = std::remove_cvref_t<decltype(field)>;
          slot.offset =
              static_cast<std::uint16_t>(reinterpret_cast<const std::byte*>(&field) - base);
          slot.type = field_type<Field, ScalarOf<D>>();
        });
      }
      slots_[next++] = slot;  // messages.cpp asserts the layout's signals fit kMaxLayoutSignals
    }
  }
}

template <typename D>
Status FieldMap<D>::encode(std::size_t index, const D& data, std::uint8_t counter,
                           CanFrame& frame) const noexcept {
  if (index >= messages_.size() || messages_[index].direction != kDirectionOf<D>) {
    return Status::invalid_argument;
  }
  using S = ScalarOf<D>;
  const MessageSpec& message = messages_[index];
  const std::span<std::uint8_t> bytes = detail::start_frame(message, frame);
  const auto* base = reinterpret_cast<const std::byte*>(&data);
  const FieldSlot* slot = &slots_[first_[index]];
  Status status = Status::ok;
  for (const SignalSpec& s : message.signals) {
    const std::byte* at = base + slot->offset;
    Status fitted = Status::ok;
    switch ((slot++)->type) {
      case FieldType::none:
        break;
      case FieldType::scalar:
        fitted = detail::encode_physical(s, load<S>(at), bytes);
        break;
      case FieldType::flag:
        fitted = encode_raw_signal(s, static_cast<std::int64_t>(load<bool>(at)), bytes);
        break;
      case FieldType::u8:
        fitted = encode_raw_signal(s, static_cast<std::int64_t>(load<std::uint8_t>(at)), bytes);
        break;
      case FieldType::u16:
        fitted = encode_raw_signal(s, static_cast<std::int64_t>(load<std::uint16_t>(at)), bytes);
        break;
      case FieldType::u32:
        fitted = encode_raw_signal(s, static_cast<std::int64_t>(load<std::uint32_t>(at)), bytes);
        break;
    }
    if (fitted != Status::ok) {
      status = Status::out_of_range;
    }
  }
  e2e_protect(frame, message.data_id(), counter);
  return status;
}

template <typename D>
Status FieldMap<D>::decode(std::size_t index, const CanFrame& frame, D& data) const noexcept {
  if (index >= messages_.size() || messages_[index].direction != kDirectionOf<D>) {
    return Status::invalid_argument;
  }
  using S = ScalarOf<D>;
  const MessageSpec& message = messages_[index];
  if (frame.len != message.len || frame.fd != message.fd) {
    return Status::invalid_argument;
  }
  const std::span<const std::uint8_t> bytes(frame.data.data(), frame.len);
  auto* base = reinterpret_cast<std::byte*>(&data);
  const FieldSlot* slot = &slots_[first_[index]];
  for (const SignalSpec& s : message.signals) {
    std::byte* at = base + slot->offset;
    switch ((slot++)->type) {
      case FieldType::none:
        break;
      case FieldType::scalar:
        store(at, detail::decode_physical<S>(s, bytes));
        break;
      case FieldType::flag:
        store(at, static_cast<bool>(decode_raw_signal(s, bytes)));
        break;
      case FieldType::u8:
        store(at, static_cast<std::uint8_t>(decode_raw_signal(s, bytes)));
        break;
      case FieldType::u16:
        store(at, static_cast<std::uint16_t>(decode_raw_signal(s, bytes)));
        break;
      case FieldType::u32:
        store(at, static_cast<std::uint32_t>(decode_raw_signal(s, bytes)));
        break;
    }
  }
  return Status::ok;
}

template class FieldMap<RigData>;
template class FieldMap<NodeData>;
template class FieldMap<RigDataFixed>;
template class FieldMap<NodeDataFixed>;

}  // namespace tread::proto
