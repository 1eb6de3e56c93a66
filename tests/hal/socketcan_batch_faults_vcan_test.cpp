// What SocketCanBus's batches do when the kernel refuses part of one. sendmmsg and recvmmsg are
// wrapped at link time (-Wl,--wrap), so that a script can make a call fail as a real controller's
// socket does under load (a full transmit queue, ENOBUFS, after part of a batch went out), as a
// signal does (EINTR), as a dead link does (ENETDOWN), or hand over a message that is no CAN frame.
// vcan0's frames never meet a full queue, so only injection shows these paths. Every call the
// script does not fail goes to the real system call on a real socket: needs vcan0 (VM harness).
#include <gtest/gtest.h>
#include <sys/socket.h>

#include <array>
#include <cerrno>
#include <chrono>
#include <cstddef>
#include <thread>
#include <vector>

#include "socketcan/socketcan_bus.hpp"

namespace {

/// One scripted call: `fail_errno` 0 lets it through to the kernel, at most `pass_at_most` messages
/// of it (sendmmsg) or with message `malformed` (if ≥ 0) given a size no CAN frame has (recvmmsg).
struct Step {
  int fail_errno{0};
  unsigned int pass_at_most{~0U};
  int malformed{-1};
};

struct Script {
  std::array<Step, 8> steps{};
  std::size_t count{0};
  std::size_t next{0};
  std::size_t calls{0};

  void set(std::initializer_list<Step> list) {
    count = 0;
    next = 0;
    calls = 0;
    for (const Step& s : list) {
      steps[count++] = s;
    }
  }
  /// The next step, or one that lets the call through once the script is done.
  Step take() {
    ++calls;
    return next < count ? steps[next++] : Step{};
  }
};

Script g_send;
Script g_receive;

}  // namespace

extern "C" int __real_sendmmsg(int fd, mmsghdr* messages, unsigned int count, int flags);
extern "C" int __real_recvmmsg(int fd, mmsghdr* messages, unsigned int count, int flags,
                               timespec* timeout);

extern "C" int __wrap_sendmmsg(int fd, mmsghdr* messages, unsigned int count, int flags) {
  const Step step = g_send.take();
  if (step.fail_errno != 0) {
    errno = step.fail_errno;
    return -1;
  }
  return __real_sendmmsg(fd, messages, std::min(count, step.pass_at_most), flags);
}

extern "C" int __wrap_recvmmsg(int fd, mmsghdr* messages, unsigned int count, int flags,
                               timespec* timeout) {
  const Step step = g_receive.take();
  if (step.fail_errno != 0) {
    errno = step.fail_errno;
    return -1;
  }
  const int got = __real_recvmmsg(fd, messages, count, flags, timeout);
  if (step.malformed >= 0 && step.malformed < got) {
    messages[step.malformed].msg_len = 7;  // neither CAN_MTU nor CANFD_MTU
  }
  return got;
}

namespace tread::hal {
namespace {

constexpr const char* kInterface = "vcan0";

std::vector<proto::CanFrame> numbered(std::size_t count, std::uint32_t first_id) {
  std::vector<proto::CanFrame> frames(count);
  for (std::size_t i = 0; i < count; ++i) {
    frames[i].id = first_id + static_cast<std::uint32_t>(i);
    frames[i].len = 1;
    frames[i].data[0] = static_cast<std::uint8_t>(i);
  }
  return frames;
}

/// The ids `bus` receives within 200 ms of quiet (frame by frame: not the path under test).
std::vector<std::uint32_t> ids_received(SocketCanBus& bus) {
  std::vector<std::uint32_t> ids;
  auto quiet_until = std::chrono::steady_clock::now() + std::chrono::milliseconds(200);
  proto::CanFrame f{};
  while (std::chrono::steady_clock::now() < quiet_until) {
    if (bus.receive(f) == Status::ok) {
      ids.push_back(f.id);
      quiet_until = std::chrono::steady_clock::now() + std::chrono::milliseconds(200);
    } else {
      std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
  }
  return ids;
}

struct Pair {
  Pair() {
    g_send.set({});
    g_receive.set({});
    EXPECT_EQ(tx.open(kInterface, false), Status::ok) << "errno " << tx.last_errno();
    EXPECT_EQ(rx.open(kInterface, false), Status::ok) << "errno " << rx.last_errno();
  }
  ~Pair() {
    g_send.set({});
    g_receive.set({});
  }
  SocketCanBus tx;
  SocketCanBus rx;
};

// The kernel takes part of a batch, then refuses the call that starts at the next frame: a full
// queue counts that frame and all after it as dropped; a dead link is an error, not drops.
TEST(SocketCanBatchFaults, APartlyTakenBatchCountsDropsOnlyForAFullQueue) {
  struct Case {
    int refusal;
    std::size_t frames;
    unsigned int taken;
    std::uint64_t dropped;
  };
  for (const Case c : {Case{ENOBUFS, 5, 3, 2}, Case{ENETDOWN, 6, 2, 0}}) {
    SCOPED_TRACE(c.refusal);
    Pair p;
    const std::vector<proto::CanFrame> frames = numbered(c.frames, 0x400);
    g_send.set({{0, c.taken}, {c.refusal}});
    EXPECT_EQ(p.tx.send_batch(frames), c.taken);
    EXPECT_EQ(p.tx.tx_dropped(), c.dropped);
    EXPECT_EQ(p.tx.last_errno(), c.refusal);
    EXPECT_EQ(g_send.calls, 2U);
    std::vector<std::uint32_t> expected;
    for (std::uint32_t k = 0; k < c.taken; ++k) {
      expected.push_back(0x400 + k);
    }
    EXPECT_EQ(ids_received(p.rx), expected);
  }
}

TEST(SocketCanBatchFaults, AFullQueueAtOnceDropsTheWholeBatchOfSeveralCalls) {
  Pair p;
  // Two system calls' worth; the first is refused outright (EAGAIN: a non-blocking socket).
  const std::vector<proto::CanFrame> frames = numbered(SocketCanBus::kBatchFrames + 8, 0x400);
  g_send.set({{EAGAIN}});
  EXPECT_EQ(p.tx.send_batch(frames), 0U);
  EXPECT_EQ(p.tx.tx_dropped(), frames.size());
  EXPECT_EQ(g_send.calls, 1U);  // the rest is not tried against a full queue
  EXPECT_TRUE(ids_received(p.rx).empty());
  // The queue has room again: the next batch goes, in two calls.
  EXPECT_EQ(p.tx.send_batch(frames), frames.size());
  EXPECT_EQ(g_send.calls, 3U);
  EXPECT_EQ(ids_received(p.rx).size(), frames.size());
  EXPECT_EQ(p.tx.tx_dropped(), frames.size());
}

TEST(SocketCanBatchFaults, ASignalIsRetriedAndNothingIsLost) {
  Pair p;
  const std::vector<proto::CanFrame> frames = numbered(4, 0x410);
  g_send.set({{0, 1U}, {EINTR}, {EINTR}});
  EXPECT_EQ(p.tx.send_batch(frames), 4U);
  EXPECT_EQ(p.tx.tx_dropped(), 0U);
  EXPECT_EQ(p.tx.last_errno(), 0);  // a signal is no error
  EXPECT_EQ(ids_received(p.rx), (std::vector<std::uint32_t>{0x410, 0x411, 0x412, 0x413}));
}

TEST(SocketCanBatchFaults, AMessageThatIsNoCanFrameIsSkippedAndCounted) {
  Pair p;
  const std::vector<proto::CanFrame> frames = numbered(3, 0x430);
  ASSERT_EQ(p.tx.send_batch(frames), 3U);
  std::this_thread::sleep_for(std::chrono::milliseconds(50));  // all three queued at the reader
  g_receive.set({{EINTR}, {0, ~0U, 1}});  // a signal first; then the middle one is malformed
  std::array<proto::CanFrame, 8> got{};
  ASSERT_EQ(p.rx.receive_batch(got), 2U);
  EXPECT_EQ(got[0].id, 0x430U);
  EXPECT_EQ(got[1].id, 0x432U);
  EXPECT_GT(got[1].timestamp_ns, 0);
  EXPECT_EQ(p.rx.rx_malformed(), 1U);
  EXPECT_EQ(p.rx.receive_batch(got), 0U);
  EXPECT_EQ(p.rx.last_errno(), 0);  // an empty queue is no error
}

}  // namespace
}  // namespace tread::hal
