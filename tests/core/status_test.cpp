#include "core/status.hpp"

#include <gtest/gtest.h>

#include <cstring>

namespace tread {
namespace {

TEST(Status, EveryStatusHasADistinctName) {
  const Status all[] = {Status::ok,          Status::out_of_range, Status::invalid_argument,
                        Status::bad_crc,     Status::bad_counter,  Status::timeout,
                        Status::would_block, Status::io_error,     Status::unsupported,
                        Status::non_finite};
  for (std::size_t i = 0; i < std::size(all); ++i) {
    for (std::size_t j = i + 1; j < std::size(all); ++j) {
      EXPECT_STRNE(to_string(all[i]), to_string(all[j]));
    }
  }
  EXPECT_STREQ(to_string(Status::bad_crc), "bad CRC");
  EXPECT_STREQ(to_string(Status::non_finite), "non-finite result");
}

TEST(Result, OkOnlyWithStatusOk) {
  constexpr Result<int> good{7, Status::ok};
  constexpr Result<int> bad{0, Status::out_of_range};
  static_assert(good.ok());
  static_assert(!bad.ok());
  EXPECT_EQ(good.value, 7);
}

}  // namespace
}  // namespace tread
