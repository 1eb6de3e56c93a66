#pragma once
// Reader → workers → ordered writer (host side): the shape of a stream processed in chunks on
// every core, its output in input order, its memory bounded by the chunks in flight rather than
// the length of the stream.
//
// The calling thread makes items (`produce`, e.g. reads a chunk of lines) and hands them in
// order to `consume` (e.g. writes them); `workers` threads run `work` on them in between, several
// at once. A fixed ring of `in_flight` items is reused, so their buffers are allocated once.
// An exception from `work` is kept with its item and thrown on the calling thread when that item's
// turn to be consumed comes: the first error in input order wins, and everything before it has
// been consumed. An exception from `produce` or `consume` stops the workers (items not started are
// dropped, those running finish) and propagates too.

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace tread::host {

/// Worker threads for a machine: one per hardware thread (at least one).
inline unsigned default_worker_count() {
  const unsigned n = std::thread::hardware_concurrency();
  return n == 0 ? 1 : n;
}

/// Runs the pipeline to the end of the input (produce returned false) or the first exception.
/// `produce(Item&)` → bool and `consume(Item&)` run on the calling thread, `work(Item&)` on the
/// workers; `in_flight` ≥ 1 items exist at once (2 × workers + 2 keeps every worker busy while the
/// caller writes).
template <typename Item, typename Produce, typename Work, typename Consume>
void run_ordered_pipeline(unsigned workers, std::size_t in_flight, Produce&& produce, Work&& work,
                          Consume&& consume) {
  struct Slot {
    Item item{};
    std::exception_ptr error;
    bool done = false;
  };
  if (workers == 0) workers = 1;
  if (in_flight == 0) in_flight = 1;
  std::vector<Slot> slots(in_flight);
  std::mutex mutex;
  std::condition_variable work_ready;
  std::condition_variable work_done;
  std::deque<Slot*> queue;
  bool stopping = false;

  std::vector<std::thread> threads;
  threads.reserve(workers);
  const auto stop = [&] {
    {
      const std::lock_guard<std::mutex> lock(mutex);
      stopping = true;
      queue.clear();
    }
    work_ready.notify_all();
    for (std::thread& t : threads) t.join();
    threads.clear();
  };
  try {
    // Started inside the try: if starting one fails, those already running are stopped and
    // joined (a joinable std::thread destroyed would end the program).
    for (unsigned i = 0; i < workers; ++i) {
      threads.emplace_back([&] {
        while (true) {
          Slot* slot = nullptr;
          {
            std::unique_lock<std::mutex> lock(mutex);
            work_ready.wait(lock, [&] { return stopping || !queue.empty(); });
            if (queue.empty()) return;  // stopping
            slot = queue.front();
            queue.pop_front();
          }
          try {
            work(slot->item);
          } catch (...) {
            slot->error = std::current_exception();
          }
          {
            const std::lock_guard<std::mutex> lock(mutex);
            slot->done = true;
          }
          work_done.notify_all();
        }
      });
    }

    std::size_t made = 0;      // items produced
    std::size_t consumed = 0;  // items consumed
    bool end = false;
    while (true) {
      while (!end && made - consumed < in_flight) {
        Slot& slot = slots[made % in_flight];
        slot.error = nullptr;
        slot.done = false;
        if (!produce(slot.item)) {
          end = true;
          break;
        }
        {
          const std::lock_guard<std::mutex> lock(mutex);
          queue.push_back(&slot);
        }
        work_ready.notify_one();
        ++made;
      }
      if (consumed == made) break;
      Slot& slot = slots[consumed % in_flight];
      {
        std::unique_lock<std::mutex> lock(mutex);
        work_done.wait(lock, [&] { return slot.done; });
      }
      if (slot.error) std::rethrow_exception(slot.error);
      consume(slot.item);
      ++consumed;
    }
  } catch (...) {
    stop();
    throw;
  }
  stop();
}

}  // namespace tread::host
