#include "core/sha256.hpp"

#include <gtest/gtest.h>

#include <string>

namespace haptex {
namespace {

// FIPS 180-4 example vectors (also what Python's hashlib.sha256 prints).
TEST(Sha256, KnownVectors) {
  EXPECT_EQ(Sha256().hex_digest(), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  Sha256 abc;
  abc.update("abc");
  EXPECT_EQ(abc.hex_digest(), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  Sha256 two_blocks;
  two_blocks.update("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq");
  EXPECT_EQ(two_blocks.hex_digest(), "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
}

TEST(Sha256, ChunkedUpdatesMatchOneShot) {
  std::string text(1000, 'a');
  for (std::size_t i = 0; i < text.size(); ++i) text[i] = char('a' + i % 26);
  Sha256 whole;
  whole.update(text);
  Sha256 pieces;
  for (std::size_t i = 0; i < text.size(); i += 37) pieces.update(std::string_view(text).substr(i, 37));
  EXPECT_EQ(whole.hex_digest(), pieces.hex_digest());
}

TEST(Sha256, CpuExtensionsAndPortableCodeAgree) {
  if (!Sha256::cpu_extensions_available()) GTEST_SKIP() << "this CPU has no SHA extensions; only the portable code runs";
  std::string text(100000, '\0');
  for (std::size_t i = 0; i < text.size(); ++i) text[i] = char((i * 7919) % 251);
  Sha256 fast;
  fast.update(text);
  Sha256::use_cpu_extensions = false;
  Sha256 portable;
  portable.update(text);
  const std::string portable_hex = portable.hex_digest();
  Sha256::use_cpu_extensions = true;
  EXPECT_EQ(fast.hex_digest(), portable_hex);
}

TEST(Sha256, MillionAs) {
  Sha256 hash;
  std::string block(1000, 'a');
  for (int i = 0; i < 1000; ++i) hash.update(block);
  EXPECT_EQ(hash.hex_digest(), "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

}  // namespace
}  // namespace haptex
