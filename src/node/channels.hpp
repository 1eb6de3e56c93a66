#pragma once
// What the node computes per channel, as concepts: a road-wheel tyre (Magic Formula + optional
// relaxation) and a rail wheelset (contact lookup table). The node is generic over both, so it is
// tested with simple channels and runs with the real ones, without virtual dispatch.

#include <concepts>
#include <cstddef>
#include <cstdint>
#include <span>

#include "proto/codec.hpp"

namespace tread::node {

struct TyreResult {
  float fx_n{0.0F};
  float fy_n{0.0F};
  float mz_nm{0.0F};
  float mx_nm{0.0F};
  float my_nm{0.0F};
  float rl_m{0.0F};
  bool clamped{false};  ///< an input was outside the model's limits and was clamped to them
  /// the model gave a non-finite output (defective parameters, a NaN input): not to be sent
  bool non_finite{false};
};

struct ContactResult {
  float r_left_mm{0.0F};
  float r_right_mm{0.0F};
  float delta_r_mm{0.0F};
  float gamma_left_rad{0.0F};
  float gamma_right_rad{0.0F};
  bool clamped{false};  ///< the displacement lay outside the table and was clamped to its range
};

/// A road-wheel channel. `dt_s` is the time since the previous evaluation (0 on the first one).
template <typename T>
concept TyreChannel = requires(T tyre, const proto::WheelInput& input, float dt_s) {
  { tyre.evaluate(input, dt_s) } -> std::same_as<TyreResult>;
  { tyre.reset() } -> std::same_as<void>;
};

/// Whether wheel i is among the due wheels of a cycle (bit i of `due`).
constexpr bool is_due(std::uint8_t due, std::size_t i) {
  return ((static_cast<unsigned>(due) >> i) & 1U) != 0U;
}

/// A tyre channel type that evaluates the due wheels of a cycle in one call (e.g. four wheels on
/// vector lanes): results[i] for every bit i of `due`; the node uses it when the type has it.
template <typename T>
concept BatchTyreChannel = TyreChannel<T> &&
    requires(std::span<T> tyres, std::span<const proto::WheelInput> inputs, std::uint8_t due,
             float dt_s, std::span<TyreResult> results) {
  { T::evaluate_wheels(tyres, inputs, due, dt_s, results) } -> std::same_as<void>;
};

/// A rail-wheelset channel.
template <typename C>
concept ContactChannel = requires(C contact, const proto::WheelsetInput& input) {
  { contact.evaluate(input) } -> std::same_as<ContactResult>;
};

/// A channel type for builds without wheelsets (or without road wheels).
struct NoContact {
  ContactResult evaluate(const proto::WheelsetInput& /*input*/) const noexcept { return {}; }
};
struct NoTyre {
  TyreResult evaluate(const proto::WheelInput& /*input*/, float /*dt_s*/) const noexcept {
    return {};
  }
  void reset() noexcept {}
};
static_assert(TyreChannel<NoTyre> && ContactChannel<NoContact>);

}  // namespace tread::node
