// host::run_ordered_pipeline (sim/io/ordered_pipeline.hpp): items are consumed in the order they
// were made whatever the workers' timing; the first failing item in that order is the error, after
// every item before it was consumed; a failing consumer stops the pipeline.
#include "io/ordered_pipeline.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <random>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace {

struct Item {
  int index = 0;
  long long square = 0;
  std::vector<int> buffer;  // reused across items
};

// Work that takes a random few microseconds, so items finish out of order.
void slow_square(Item& item) {
  thread_local std::mt19937 rng(std::random_device{}());
  std::this_thread::sleep_for(std::chrono::microseconds(rng() % 200));
  item.square = static_cast<long long>(item.index) * item.index;
  item.buffer.assign(16, item.index);
}

TEST(OrderedPipeline, ConsumesInOrder) {
  for (const unsigned workers : {1U, 2U, 4U}) {
    for (const std::size_t in_flight : {1U, 2U, 6U}) {
      int made = 0;
      std::vector<long long> consumed;
      tread::host::run_ordered_pipeline<Item>(
          workers, in_flight,
          [&](Item& item) {
            if (made == 500) return false;
            item.index = made++;
            return true;
          },
          slow_square,
          [&](Item& item) {
            EXPECT_EQ(item.buffer.front(), item.index);
            consumed.push_back(item.square);
          });
      ASSERT_EQ(consumed.size(), 500U);
      for (std::size_t i = 0; i < consumed.size(); ++i) {
        ASSERT_EQ(consumed[i], static_cast<long long>(i * i)) << workers << ' ' << in_flight;
      }
    }
  }
}

TEST(OrderedPipeline, FirstErrorInInputOrderAfterEverythingBefore) {
  int made = 0;
  std::vector<int> consumed;
  try {
    tread::host::run_ordered_pipeline<Item>(
        3, 8,
        [&](Item& item) {
          if (made == 1000) return false;
          item.index = made++;
          return true;
        },
        [](Item& item) {
          slow_square(item);
          // 37 fails slowly, later ones at once: 37 is still the error.
          if (item.index == 37) {
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
            throw std::runtime_error("item 37");
          }
          if (item.index > 37 && item.index % 2 == 0) throw std::runtime_error("later item");
        },
        [&](Item& item) { consumed.push_back(item.index); });
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "item 37");
  }
  ASSERT_EQ(consumed.size(), 37U);
  for (int i = 0; i < 37; ++i) EXPECT_EQ(consumed[static_cast<std::size_t>(i)], i);
  EXPECT_LT(made, 1000);  // reading stopped
}

TEST(OrderedPipeline, FailingConsumerStopsThePipeline) {
  int made = 0;
  EXPECT_THROW(tread::host::run_ordered_pipeline<Item>(
                   2, 4,
                   [&](Item& item) {
                     item.index = made++;
                     return true;  // endless input
                   },
                   slow_square,
                   [](Item& item) {
                     if (item.index == 10) throw std::runtime_error("disk full");
                   }),
               std::runtime_error);
  EXPECT_LT(made, 20);
}

}  // namespace
