#pragma once
// A rail-wheelset channel on a precomputed contact table (rail/contact_lookup.hpp).
#include "node/channels.hpp"
#include "rail/contact_lookup.hpp"

namespace tread::node {

class ContactTableChannel {
 public:
  ContactTableChannel() = default;
  /// The table's columns must outlive the channel.
  explicit ContactTableChannel(const rail::ContactTableF32& table) noexcept : table_(table) {}

  ContactResult evaluate(const proto::WheelsetInput& in) const noexcept {
    const Result<rail::ContactSample> r = rail::lookup(table_, in.lateral_mm);
    ContactResult out;
    if (r.status == Status::invalid_argument) {
      out.clamped = true;
      return out;
    }
    out.r_left_mm = r.value.r_left_mm;
    out.r_right_mm = r.value.r_right_mm;
    out.delta_r_mm = r.value.delta_r_mm;
    out.gamma_left_rad = r.value.gamma_left_rad;
    out.gamma_right_rad = r.value.gamma_right_rad;
    out.clamped = r.status == Status::out_of_range;
    return out;
  }

 private:
  rail::ContactTableF32 table_{};
};

static_assert(ContactChannel<ContactTableChannel>);

}  // namespace tread::node
