#pragma once
// What the node computes per channel, as concepts: a road-wheel tyre (Magic Formula + optional
// relaxation) and a rail wheelset (contact lookup table). The node is generic over both, so it is
// tested with simple channels and runs with the real ones, without virtual dispatch.

#include <concepts>
#include <cstddef>
#include <cstdint>
#include <span>

#include "fixed/fixed64.hpp"
#include "proto/data_model.hpp"

namespace tread::node {

/// The results in the channel's scalar: float, or fixed::Fixed64 on the integer-only path. Each is
/// the output's values (data_model.hpp) and what the model says about them.
template <typename S>
struct BasicTyreResult : proto::BasicWheelValues<S> {
  bool clamped{false};  ///< an input was outside the model's limits and was clamped to them
  /// the model gave a non-finite output (defective parameters, a NaN input): not to be sent
  bool non_finite{false};
};
using TyreResult = BasicTyreResult<float>;
using TyreResultFixed = BasicTyreResult<fixed::Fixed64>;

template <typename S>
struct BasicContactResult : proto::BasicWheelsetValues<S> {
  bool clamped{false};  ///< the displacement lay outside the table and was clamped to its range
};
using ContactResult = BasicContactResult<float>;
using ContactResultFixed = BasicContactResult<fixed::Fixed64>;

/// One rail wheel's contact forces (the values of proto::BasicRailWheelOutput).
template <typename S>
struct BasicRailWheelForces : proto::BasicRailWheelValues<S> {
  bool lifted{false};  ///< no load on the wheel: no Y/Q (reported 0, margin = the limit)
};

using RailWheelForces = BasicRailWheelForces<float>;

template <typename S>
struct BasicRailForceResult {
  BasicRailWheelForces<S> wheel[2];  ///< left, right
  bool clamped{false};  ///< the displacement lay outside the table and was clamped to its range
};
using RailForceResult = BasicRailForceResult<float>;

/// The scalar a channel computes in: its `Scalar` member type, float when it has none.
template <typename T>
struct channel_scalar {
  using type = float;
};
template <typename T>
requires requires {
  typename T::Scalar;
}
struct channel_scalar<T> {
  using type = typename T::Scalar;
};
template <typename T>
using ChannelScalar = typename channel_scalar<T>::type;

/// A road-wheel channel. `dt_s` is the time since the previous evaluation (0 on the first one).
template <typename T>
concept TyreChannel = requires(T tyre, const proto::BasicWheelInput<ChannelScalar<T>>& input,
                               ChannelScalar<T> dt_s) {
  { tyre.evaluate(input, dt_s) } -> std::same_as<BasicTyreResult<ChannelScalar<T>>>;
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
    requires(std::span<T> tyres, std::span<const proto::BasicWheelInput<ChannelScalar<T>>> inputs,
             std::uint8_t due, ChannelScalar<T> dt_s,
             std::span<BasicTyreResult<ChannelScalar<T>>> results) {
  { T::evaluate_wheels(tyres, inputs, due, dt_s, results) } -> std::same_as<void>;
};

/// A rail-wheelset channel.
template <typename C>
concept ContactChannel = requires(C contact,
                                  const proto::BasicWheelsetInput<ChannelScalar<C>>& input) {
  { contact.evaluate(input) } -> std::same_as<BasicContactResult<ChannelScalar<C>>>;
};

/// A wheel-rail force channel: the wheelset's contact forces from its displacement, motion and
/// wheel loads.
template <typename C>
concept RailForceChannel = requires(C forces,
                                    const proto::BasicWheelsetInput<ChannelScalar<C>>& input) {
  { forces.evaluate(input) } -> std::same_as<BasicRailForceResult<ChannelScalar<C>>>;
};

/// No wheel-rail forces (in the scalar S of the node's other channels).
template <typename S>
struct NoRailForce {
  using Scalar = S;
  BasicRailForceResult<S> evaluate(const proto::BasicWheelsetInput<S>& /*input*/) const noexcept {
    BasicRailForceResult<S> none;
    return none;
  }
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
static_assert(TyreChannel<NoTyre> && ContactChannel<NoContact> &&
              RailForceChannel<NoRailForce<float>>);

}  // namespace tread::node
