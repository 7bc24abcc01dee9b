// Checks shared by the house message tests (HouseMessagesTest, RoomMessagesTest): a payload's bytes, and a
// decoder refusing every truncation, trailing byte, bad byte or bad field of a good message.
#pragma once

#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "common/protocol/Messages.hpp"

namespace nxtmap::protocol::test {

using Bytes = std::vector<uint8_t>;
inline Bytes bytesOf(const Payload& p) { return Bytes(p.bytes, p.bytes + p.size); }

// A good payload of a message: truncated at every length, or one byte longer, it is refused.
template <class Msg>
void expectExactLength(const Bytes& good, bool (*dec)(const uint8_t*, size_t, Msg&)) {
  Msg d;
  ASSERT_TRUE(dec(good.data(), good.size(), d));
  for (size_t n = 0; n < good.size(); ++n) EXPECT_FALSE(dec(good.data(), n, d)) << "truncated to " << n;
  Bytes longer = good;
  longer.push_back(0);
  EXPECT_FALSE(dec(longer.data(), longer.size(), d)) << "trailing byte";
}

// A malformed case: byte `at` of the good payload set to `value`.
struct BadByte {
  const char* what;
  size_t at;
  uint8_t value;
};
template <class Msg>
void expectRefused(const Bytes& good, const std::vector<BadByte>& bads, bool (*dec)(const uint8_t*, size_t, Msg&)) {
  for (const BadByte& b : bads) {
    Bytes x = good;
    ASSERT_LT(b.at, x.size()) << b.what;
    x[b.at] = b.value;
    Msg d;
    EXPECT_FALSE(dec(x.data(), x.size(), d)) << b.what;
  }
}

// A malformed message built from fields (encoders write what they are given).
template <class Msg>
struct BadMsg {
  const char* what;
  std::function<void(Msg&)> spoil;
};
template <class Msg>
void expectRefused(const Msg& good, const std::vector<BadMsg<Msg>>& bads, size_t (*enc)(const Msg&, Payload&),
                   bool (*dec)(const uint8_t*, size_t, Msg&)) {
  for (const BadMsg<Msg>& b : bads) {
    Msg x = good;
    b.spoil(x);
    Payload p;
    ASSERT_GT(enc(x, p), 0u) << b.what;
    Msg d;
    EXPECT_FALSE(dec(p.bytes, p.size, d)) << b.what;
  }
}

}  // namespace nxtmap::protocol::test
