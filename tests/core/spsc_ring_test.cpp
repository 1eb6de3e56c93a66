#include "core/spsc_ring.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <thread>

namespace tread::core {
namespace {

TEST(SpscRing, KeepsOrderRefusesWhenFullAndWhenEmpty) {
  SpscRing<int, 4> ring;
  int v = 0;
  EXPECT_FALSE(ring.pop(v));
  for (int i = 0; i < 4; ++i) {
    EXPECT_TRUE(ring.push(i));
  }
  EXPECT_FALSE(ring.push(99));  // full: refused, nothing overwritten
  EXPECT_EQ(ring.size(), 4U);
  for (int i = 0; i < 4; ++i) {
    ASSERT_TRUE(ring.pop(v));
    EXPECT_EQ(v, i);
  }
  EXPECT_FALSE(ring.pop(v));
  EXPECT_TRUE(ring.empty());
}

TEST(SpscRing, WrapsAroundItsIndicesManyTimes) {
  SpscRing<std::uint32_t, 8> ring;
  std::uint32_t next_in = 0;
  std::uint32_t next_out = 0;
  for (int round = 0; round < 10'000; ++round) {
    for (int k = 0; k < 5; ++k) {
      ASSERT_TRUE(ring.push(next_in++));
    }
    std::uint32_t v = 0;
    while (ring.pop(v)) {
      ASSERT_EQ(v, next_out++);
    }
  }
  EXPECT_EQ(next_out, 50'000U);
}

// One producer thread, one consumer thread: every element arrives once, in order, unchanged.
TEST(SpscRing, HandsEveryElementFromOneThreadToAnotherInOrder) {
  struct Item {
    std::uint64_t seq;
    std::uint64_t check;
  };
  SpscRing<Item, 64> ring;
  constexpr std::uint64_t kItems = 1'000'000;
  std::thread producer([&ring] {
    for (std::uint64_t i = 0; i < kItems;) {
      if (ring.push(Item{i, ~i})) {
        ++i;
      }
    }
  });
  std::uint64_t expected = 0;
  std::uint64_t bad = 0;
  Item item{};
  while (expected < kItems) {
    if (ring.pop(item)) {
      bad += (item.seq != expected || item.check != ~expected) ? 1U : 0U;
      ++expected;
    }
  }
  producer.join();
  EXPECT_EQ(bad, 0U);
  EXPECT_TRUE(ring.empty());
}

}  // namespace
}  // namespace tread::core
