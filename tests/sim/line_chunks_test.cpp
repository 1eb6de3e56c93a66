// host::LineChunker (sim/io/line_chunks.hpp): whole lines, numbered, in chunks of at most N lines;
// the text comes out whole, whatever the chunk size, with or without a final newline; the line
// ends the chunker records give the lines a search for '\n' gives.
#include "io/line_chunks.hpp"

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

namespace {

using tread::host::LineChunk;
using tread::host::LineChunker;

struct Line {
  std::string text;
  int number;
  bool operator==(const Line&) const = default;
};

std::vector<Line> lines_of(const std::string& text, std::size_t per_chunk, int first_line,
                           const std::string& pending, std::size_t* chunks = nullptr) {
  std::istringstream in(text);
  LineChunker chunker(in, "in.csv", per_chunk, first_line, pending);
  LineChunk chunk;
  std::vector<Line> lines;
  std::size_t n = 0;
  std::string whole;
  while (chunker.next(chunk)) {
    ++n;
    EXPECT_LE(chunk.lines, per_chunk);
    EXPECT_EQ(chunk.first_line, first_line + static_cast<int>(lines.size()));
    std::size_t seen = 0;
    tread::host::for_each_line(chunk, [&](std::string_view line, int number) {
      lines.push_back({std::string(line), number});
      ++seen;
    });
    EXPECT_EQ(seen, chunk.lines);
    // The chunker's line ends are the lines' '\n' (or the text's end): the same lines as a search.
    EXPECT_EQ(chunk.ends.size(), chunk.lines);
    LineChunk searched = chunk;
    searched.ends.clear();
    std::size_t at = lines.size() - seen;
    tread::host::for_each_line(searched, [&](std::string_view line, int number) {
      ASSERT_LT(at, lines.size());
      EXPECT_EQ(line, lines[at].text);
      EXPECT_EQ(number, lines[at].number);
      ++at;
    });
    EXPECT_EQ(at, lines.size());
    whole += chunk.text;
  }
  EXPECT_EQ(whole, pending + text);
  EXPECT_EQ(chunker.bytes(), whole.size());
  if (chunks != nullptr) *chunks = n;
  return lines;
}

TEST(LineChunks, WholeNumberedLinesInEveryChunkSize) {
  std::string text;
  std::vector<Line> expected = {{"first", 5}};
  for (int i = 0; i < 1000; ++i) {
    const std::string line = i % 7 == 0 ? ""
                                        : "line " + std::to_string(i) +
                                              std::string(static_cast<std::size_t>(i % 300), 'x');
    text += line + (i % 11 == 0 ? "\r\n" : "\n");
    expected.push_back({line + (i % 11 == 0 ? "\r" : ""), 6 + i});
  }
  for (const std::size_t per_chunk : {1U, 2U, 3U, 999U, 1000U, 1001U, 100000U}) {
    std::size_t chunks = 0;
    EXPECT_EQ(lines_of(text, per_chunk, 5, "first\n", &chunks), expected) << per_chunk;
    EXPECT_EQ(chunks, (1001 + per_chunk - 1) / per_chunk) << per_chunk;
  }
}

TEST(LineChunks, LastLineWithoutNewlineAndEmptyInput) {
  const std::vector<Line> expected = {{"a", 1}, {"b", 2}, {"c", 3}};
  EXPECT_EQ(lines_of("a\nb\nc", 2, 1, ""), expected);
  EXPECT_EQ(lines_of("a\nb\nc\n", 2, 1, ""), expected);
  EXPECT_TRUE(lines_of("", 4, 1, "").empty());
  // Long lines (beyond one read of the stream).
  const std::string long_line(300000, 'y');
  const std::vector<Line> longs = {{long_line, 1}, {"z", 2}, {long_line, 3}};
  EXPECT_EQ(lines_of(long_line + "\nz\n" + long_line, 1, 1, ""), longs);
}

}  // namespace
