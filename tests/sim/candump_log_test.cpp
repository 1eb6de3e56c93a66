#include "runtime/candump_log.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "test_dir.hpp"

namespace tread::host {
namespace {

TEST(CandumpLog, FormatsClassicFdExtendedAndErrorFramesAsCandumpDoes) {
  char line[kCandumpLineMax];
  proto::CanFrame f{};
  f.id = 0x123;
  f.len = 4;
  f.data[0] = 0xDE;
  f.data[1] = 0xAD;
  f.data[2] = 0xBE;
  f.data[3] = 0xEF;
  format_candump_line(f, 1'700'000'000'123'456'789LL, "vcan0", line);
  EXPECT_STREQ(line, "(1700000000.123456) vcan0 123#DEADBEEF");
  f.extended = true;
  f.id = 0x1ABCDE;
  format_candump_line(f, 5'000, "vcan0", line);
  EXPECT_STREQ(line, "(0.000005) vcan0 001ABCDE#DEADBEEF");
  proto::CanFrame fd{};
  fd.id = 0x0A0;
  fd.fd = true;
  fd.bit_rate_switch = true;
  fd.len = 12;
  format_candump_line(fd, 0, "can1", line);
  EXPECT_STREQ(line, "(0.000000) can1 0A0##1000000000000000000000000");
  proto::CanFrame err{};
  err.error = true;
  err.id = 0x40;
  err.len = 8;
  format_candump_line(err, 0, "vcan0", line);
  EXPECT_STREQ(line, "(0.000000) vcan0 20000040#0000000000000000");
}

TEST(CandumpLog, ParseIsTheInverseOfFormat) {
  for (const char* text : {"(1.000001) vcan0 123#DEADBEEF", "(12.500000) x 001ABCDE#",
                           "(0.000000) can1 0A0##1000000000000000000000000",
                           "(3.000000) vcan0 20000040#0000000000000000"}) {
    const LoggedFrame f = parse_candump_line(text, "t:1");
    char back[kCandumpLineMax];
    format_candump_line(f.frame, f.time_ns, f.interface, back);
    EXPECT_STREQ(back, text);
  }
  const LoggedFrame f = parse_candump_line("(1.000001) vcan0 123#DEADBEEF R", "t:1");
  EXPECT_EQ(f.frame.len, 4U);  // candump's direction flag is ignored
  EXPECT_EQ(f.time_ns, 1'000'001'000);
}

TEST(CandumpLog, BadLinesNameFileAndLine) {
  const char* bad[] = {"1.0 vcan0 123#00",
                       "(1.0) vcan0 123#00",
                       "(1.000000) vcan0",
                       "(1.000000) vcan0 12#00",
                       "(1.000000) vcan0 12G#00",
                       "(1.000000) vcan0 123#0",
                       "(1.000000) vcan0 123#001122334455667788",
                       "(1.000000) vcan0 123##1001122334455667788AA"};
  for (const char* text : bad) {
    try {
      parse_candump_line(text, "run.log:7");
      ADD_FAILURE() << "accepted: " << text;
    } catch (const std::runtime_error& e) {
      EXPECT_EQ(std::string(e.what()).rfind("run.log:7: ", 0), 0U) << e.what();
    }
  }
  const std::filesystem::path path =
      tread::testing::test_dir("candump_log_test") / "candump_bad_test.log";
  {
    std::ofstream out(path);
    out << "(1.000000) vcan0 123#00\n(1.000000) vcan0 123#ZZ\n";
  }
  try {
    read_candump_log(path);
    ADD_FAILURE() << "accepted a bad file";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("candump_bad_test.log:2: "), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace tread::host
