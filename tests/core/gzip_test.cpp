#include "core/gzip.hpp"

#include <gtest/gtest.h>

#include <random>
#include <string>

#include "core/error.hpp"
#include "tests/support/bad_input.hpp"
#include "tests/support/run_haptex.hpp"
#include "tests/support/sample_recording.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex {
namespace {

using test::bad_input_message;

// Numbers as a recording's text has them: 6 decimals, one per line; a few MB, so the output grows
// past zlib's first buffers.
std::string numbers_text(std::size_t lines) {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> noise;
  std::string text;
  for (std::size_t i = 0; i < lines; ++i) text += "    <value>" + std::to_string(noise(rng)) + "</value>\n";
  return text;
}

std::vector<char> unzip(const std::string& gz, std::uintmax_t max_bytes = std::uintmax_t(1) << 32) {
  return gzip::decompress(gz, max_bytes, "x.xml.gz");
}

std::string as_string(const std::vector<char>& v) { return {v.begin(), v.end()}; }

TEST(Gzip, RoundTripsAndIsDeterministic) {
  const std::string text = numbers_text(200000);  // 5.6 MB
  const std::string gz = gzip::compress(text, 1);
  EXPECT_TRUE(gzip::is_gzip(gz));
  EXPECT_LT(gz.size(), text.size() / 3);
  EXPECT_EQ(gz, gzip::compress(text, 1)) << "two runs must give the same bytes";
  EXPECT_EQ(gz.substr(4, 4), std::string(4, '\0')) << "no modification time in the header";
  EXPECT_EQ(as_string(unzip(gz)), text);
  EXPECT_EQ(as_string(unzip(gzip::compress("", 6))), "");
}

// What `gzip` and Python read, and what they write, haptex reads.
TEST(Gzip, PythonReadsWhatItWritesAndTheOtherWayRound) {
  if (!test::python_has("gzip")) GTEST_SKIP() << "python3 is not installed";
  test::TempDir dir;
  const std::string text = numbers_text(1000);
  test::write_text_file(dir.file("ours.gz"), gzip::compress(text, 1));
  const test::CommandResult r = test::run_python(
      {"-c", "import gzip, sys; t = gzip.open(sys.argv[1]).read(); gzip.open(sys.argv[2], 'wb').write(t); print(len(t))",
       dir.file("ours.gz"), dir.file("theirs.gz")});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(std::stoul(r.out), text.size());
  EXPECT_EQ(test::read_recording_text(dir.file("theirs.gz")), text);
}

TEST(Gzip, ConcatenatedMembersReadAsOne) {
  EXPECT_EQ(as_string(unzip(gzip::compress("<a>", 1) + gzip::compress("</a>\n", 9))), "<a></a>\n");
}

TEST(Gzip, CutShortIsRefusedWithTheByte) {
  const std::string gz = gzip::compress(numbers_text(10000), 1);
  for (std::size_t keep : {std::size_t(2), std::size_t(10), gz.size() / 2, gz.size() - 4}) {
    SCOPED_TRACE(keep);
    const std::string m = bad_input_message([&] { unzip(gz.substr(0, keep)); });
    EXPECT_NE(m.find("x.xml.gz"), std::string::npos) << m;
    EXPECT_NE(m.find("cut short"), std::string::npos) << m;
  }
}

TEST(Gzip, DamagedDataIsRefused) {
  std::string gz = gzip::compress(numbers_text(10000), 1);
  gz[gz.size() / 2] = char(gz[gz.size() / 2] ^ 0x55);
  const std::string m = bad_input_message([&] { unzip(gz); });
  EXPECT_NE(m.find("damaged"), std::string::npos) << m;
  EXPECT_NE(m.find("x.xml.gz: byte "), std::string::npos) << m;
  std::string bad_crc = gzip::compress("<a/>", 1);
  bad_crc[bad_crc.size() - 8] = char(bad_crc[bad_crc.size() - 8] ^ 1);  // the trailer's CRC-32
  EXPECT_NE(bad_input_message([&] { unzip(bad_crc); }).find("damaged"), std::string::npos);
}

TEST(Gzip, TrailingBytesAreRefused) {
  const std::string gz = gzip::compress("<a/>", 1);
  const std::string m = bad_input_message([&] { unzip(gz + "garbage"); });
  EXPECT_NE(m.find("byte " + std::to_string(gz.size())), std::string::npos) << m;
  EXPECT_NE(m.find("not gzip data"), std::string::npos) << m;
}

// A small file that expands enormously (a "zip bomb") stops at the limit, never held whole.
TEST(Gzip, ExpandingPastTheLimitIsRefused) {
  const std::string gz = gzip::compress(std::string(std::size_t(64) << 20, 'a'), 9);  // 64 MiB in about 64 KB
  ASSERT_LT(gz.size(), std::size_t(1) << 17);
  const std::string m = bad_input_message([&] { unzip(gz, std::uintmax_t(1) << 20); });
  EXPECT_NE(m.find("more than the limit of 1048576 bytes"), std::string::npos) << m;
  EXPECT_NE(m.find("--max-bytes"), std::string::npos) << m;
  EXPECT_EQ(unzip(gzip::compress("abc", 1), 3).size(), 3u) << "exactly the limit is allowed";
}

}  // namespace
}  // namespace haptex
