// host::ProgressBar (sim/io/progress_bar.hpp): nothing at all unless on a terminal, nothing for a
// short run, at most ten redraws a second, erased at the end.
#include "io/progress_bar.hpp"

#include <gtest/gtest.h>

#include <sstream>
#include <string>

namespace {

using tread::host::ProgressBar;

TEST(ProgressBar, SilentWhenNotATerminal) {
  std::ostringstream out;
  ProgressBar bar(out, false, 1000);
  for (int i = 0; i <= 100; ++i)
    bar.update(10U * static_cast<unsigned>(i), 5U * static_cast<unsigned>(i), 0.1 * i);
  bar.finish();
  EXPECT_EQ(out.str(), "");
}

TEST(ProgressBar, DrawnOnATerminalAfterTheDelayAndErased) {
  std::ostringstream out;
  ProgressBar bar(out, true, 2000000, 1.0);
  bar.update(1000, 10, 0.5);  // a short run so far: nothing
  EXPECT_EQ(out.str(), "");
  bar.update(1000000, 1048576, 1.0);
  const std::string first = out.str();
  EXPECT_EQ(first.front(), '\r');
  EXPECT_NE(first.find("[##########----------]  50 %"), std::string::npos) << first;
  EXPECT_NE(first.find("rows 1 048 576"), std::string::npos) << first;
  EXPECT_NE(first.find("1.05 M rows/s"), std::string::npos) << first;
  bar.update(1100000, 1100000, 1.05);  // within 0.1 s: not redrawn
  EXPECT_EQ(out.str(), first);
  bar.update(2000000, 2000000, 2.0);
  EXPECT_NE(out.str().find("100 %"), std::string::npos) << out.str();
  bar.finish();
  EXPECT_EQ(out.str().substr(out.str().size() - 4), "\r\033[K");
}

TEST(ProgressBar, UnknownSizeShowsRowsAndRate) {
  std::ostringstream out;
  ProgressBar bar(out, true, 0, 0.0);
  bar.update(5000, 45000, 0.5);
  EXPECT_EQ(out.str().find('%'), std::string::npos) << out.str();  // no share of the input
  EXPECT_NE(out.str().find("rows 45 000  90 k rows/s"), std::string::npos) << out.str();
  bar.finish();
  ProgressBar never(out, true, 0, 5.0);
  const std::string before = out.str();
  never.finish();  // never drawn: nothing to erase
  EXPECT_EQ(out.str(), before);
}

}  // namespace
