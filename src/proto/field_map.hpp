#pragma once
// A layout's signals bound to the fields of one data model once, when the map is made. The codec
// (codec.hpp) finds each signal's field through the role table for every frame; a FieldMap keeps
// where each field is (its byte offset in the data model, its type), so that the node's encode and
// decode of every cycle go from signal to field without the role look-up. Same frames, same
// values, same status as the codec's encode() and decode(). No heap.

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

#include "core/status.hpp"
#include "proto/can_frame.hpp"
#include "proto/data_model.hpp"
#include "proto/messages.hpp"

namespace tread::proto {

/// The type of the data-model field a signal carries.
enum class FieldType : std::uint8_t {
  none,    ///< no field in this data model (E2E header, or a signal of the other direction)
  scalar,  ///< the data model's scalar (float or fixed::Fixed64): scaled
  flag,    ///< bool
  u8,      ///< std::uint8_t
  u16,     ///< std::uint16_t
  u32,     ///< std::uint32_t
};

/// Where one signal's value is kept in the data model.
struct FieldSlot {
  std::uint16_t offset{0};  ///< bytes from the start of the data model
  FieldType type{FieldType::none};
};

/// D: RigData or RigDataFixed (the messages from the rig to the node), NodeData or NodeDataFixed
/// (from the node to the rig).
template <typename D>
class FieldMap {
 public:
  /// Binds every signal of every message of `layout`.
  explicit FieldMap(Layout layout) noexcept;

  /// encode(messages(layout)[index], data, counter, frame) of codec.hpp, without the role look-up.
  /// @retval Status::invalid_argument  index out of range or a message of the other direction
  Status encode(std::size_t index, const D& data, std::uint8_t counter,
                CanFrame& frame) const noexcept;
  /// decode(messages(layout)[index], frame, data) of codec.hpp, without the role look-up.
  /// @retval Status::invalid_argument  as encode, or a frame of another length or kind
  Status decode(std::size_t index, const CanFrame& frame, D& data) const noexcept;

 private:
  std::span<const MessageSpec> messages_;
  std::array<std::uint16_t, kMaxMessages> first_{};  ///< message k's slots start at first_[k]
  std::array<FieldSlot, kMaxLayoutSignals> slots_{};
};

extern template class FieldMap<RigData>;
extern template class FieldMap<NodeData>;
extern template class FieldMap<RigDataFixed>;
extern template class FieldMap<NodeDataFixed>;

}  // namespace tread::proto
