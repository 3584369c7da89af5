// The MAC and the security trailer (docs/SECURITY.md AUTH-1). hmac_sha256 reproduces every
// HMAC-SHA-256 test case of RFC 4231 ("Identifier and Test Vectors for HMAC-SHA-224,
// HMAC-SHA-256, HMAC-SHA-384, and HMAC-SHA-512", M. Nystrom, 2005, sections 4.2 to 4.8);
// channel_mac is HMAC-SHA-256 over channel || 0x00 || body and binds the channel name;
// mac_equal compares all 32 bytes; sign_encoded and mac_valid agree, and any single changed
// byte of a signed message fails; read_trailer decodes the big-endian key id and ARSN at the
// end of the message; and every function refuses a message shorter than a fingerprint and a
// trailer (kMinSignedBytes). derive_subkey reproduces libsodium's crypto_kdf vector and
// key_check_value an independently computed HMAC; neither shows the bytes of its key.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "evade/auth/mac.hpp"
#include "evade/auth/trailer.hpp"

namespace evade::auth {
namespace {

using Bytes = std::vector<std::uint8_t>;

int hex_value(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

Bytes from_hex(const std::string& hex) {
  Bytes out;
  for (std::size_t i = 0; i + 1 < hex.size(); i += 2) {
    const int hi = hex_value(hex[i]);
    const int lo = hex_value(hex[i + 1]);
    EXPECT_GE(hi, 0) << hex;
    EXPECT_GE(lo, 0) << hex;
    out.push_back(static_cast<std::uint8_t>(hi * 16 + lo));
  }
  EXPECT_EQ(hex.size() % 2, 0U) << hex;
  return out;
}

Bytes ascii(const std::string& s) { return Bytes(s.begin(), s.end()); }

std::string to_hex(const std::uint8_t* p, std::size_t n) {
  static const char* const kDigits = "0123456789abcdef";
  std::string s;
  for (std::size_t i = 0; i < n; ++i) {
    s.push_back(kDigits[p[i] >> 4U]);
    s.push_back(kDigits[p[i] & 0x0FU]);
  }
  return s;
}

std::string hmac_hex(const Bytes& key, const Bytes& msg) {
  const Mac m = hmac_sha256(key.data(), key.size(), msg.data(), msg.size());
  return to_hex(m.data(), m.size());
}

KeyBytes test_key(std::uint8_t seed) {
  KeyBytes k{};
  for (std::size_t i = 0; i < k.size(); ++i) k[i] = static_cast<std::uint8_t>(seed + 7 * i);
  return k;
}

// Writes v big-endian into p[0, n).
void put_be(std::uint8_t* p, std::uint64_t v, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) {
    p[n - 1 - i] = static_cast<std::uint8_t>(v & 0xFFU);
    v >>= 8U;
  }
}

// A synthetic 100-byte "encoded message": fingerprint and fields, then key id and ARSN.
Bytes synthetic_message(std::int32_t key_id, std::int64_t arsn) {
  Bytes b(100);
  for (std::size_t i = 0; i < b.size(); ++i) b[i] = static_cast<std::uint8_t>(3 * i + 1);
  put_be(b.data() + (b.size() - kTrailerBytes), static_cast<std::uint32_t>(key_id), 4);
  put_be(b.data() + (b.size() - kTrailerBytes + 4), static_cast<std::uint64_t>(arsn), 8);
  return b;
}

// ---- RFC 4231 section 4: HMAC-SHA-256 test cases 1 to 7 ----

TEST(HmacSha256, Rfc4231Case1ShortKey) {
  EXPECT_EQ(hmac_hex(Bytes(20, 0x0b), ascii("Hi There")),
            "b0344c61d8db38535ca8afceaf0bf12b881dc200c9833da726e9376c2e32cff7");
}

TEST(HmacSha256, Rfc4231Case2KeyShorterThanOutput) {
  EXPECT_EQ(hmac_hex(ascii("Jefe"), ascii("what do ya want for nothing?")),
            "5bdcc146bf60754e6a042426089575c75a003f089d2739839dec58b964ec3843");
}

TEST(HmacSha256, Rfc4231Case3CombinedKeyAndDataLength) {
  EXPECT_EQ(hmac_hex(Bytes(20, 0xaa), Bytes(50, 0xdd)),
            "773ea91e36800e46854db8ebd09181a72959098b3ef8c122d9635514ced565fe");
}

TEST(HmacSha256, Rfc4231Case4CombinedKeyAndDataLength) {
  EXPECT_EQ(hmac_hex(from_hex("0102030405060708090a0b0c0d0e0f10111213141516171819"),
                     Bytes(50, 0xcd)),
            "82558a389a443c0ea4cc819899f2083a85f0faa3e578f8077a2e3ff46729665b");
}

TEST(HmacSha256, Rfc4231Case5TruncatedTo128Bits) {
  // RFC 4231 gives only the first 128 bits of this output (a test of truncation): only the
  // first 16 bytes are compared.
  const Bytes key(20, 0x0c);
  const Bytes msg = ascii("Test With Truncation");
  const Mac m = hmac_sha256(key.data(), key.size(), msg.data(), msg.size());
  EXPECT_EQ(to_hex(m.data(), 16), "a3b6167473100ee06e0c796c2955552b");
}

TEST(HmacSha256, Rfc4231Case6KeyLargerThanBlock) {
  EXPECT_EQ(hmac_hex(Bytes(131, 0xaa), ascii("Test Using Larger Than Block-Size Key - Hash Key First")),
            "60e431591ee0b67f0d8a26aacbf5b77f8e0bc6213728c5140546040f0ee37f54");
}

TEST(HmacSha256, Rfc4231Case7KeyAndDataLargerThanBlock) {
  EXPECT_EQ(hmac_hex(Bytes(131, 0xaa),
                     ascii("This is a test using a larger than block-size key and a larger than "
                           "block-size data. The key needs to be hashed before being used by the "
                           "HMAC algorithm.")),
            "9b09ffa71b942fcb27635fbcd5b0e944bfdc63644f0713938a7f51535c3a35e2");
}

// ---- channel_mac ----

TEST(ChannelMac, IsHmacOfChannelZeroByteAndBody) {
  const KeyBytes key = test_key(11);
  const Bytes body = ascii("an encoded message body");
  const std::string channel = "EVADE_BURN_PLAN";
  Bytes joined = ascii(channel);
  joined.push_back(0x00);
  joined.insert(joined.end(), body.begin(), body.end());
  const Mac by_hand = hmac_sha256(key.data(), key.size(), joined.data(), joined.size());
  const Mac m = channel_mac(key, channel.c_str(), body.data(), body.size());
  EXPECT_EQ(to_hex(m.data(), m.size()), to_hex(by_hand.data(), by_hand.size()));
}

TEST(ChannelMac, DiffersWhenTheChannelDiffers) {
  const KeyBytes key = test_key(11);
  const Bytes body = ascii("an encoded message body");
  const Mac a = channel_mac(key, "EVADE_BURN_PLAN", body.data(), body.size());
  const Mac b = channel_mac(key, "EVADE_ARM", body.data(), body.size());
  const Mac c = channel_mac(key, "EVADE_BURN_PLAN", body.data(), body.size());
  EXPECT_NE(a, b);
  EXPECT_EQ(a, c);
}

TEST(ChannelMac, SeparatorKeepsChannelAndBodyApart) {
  // Without the 0x00 separator, channel "AB" + body "C" and channel "A" + body "BC" would hash
  // the same bytes.
  const KeyBytes key = test_key(5);
  const Bytes c = ascii("C");
  const Bytes bc = ascii("BC");
  EXPECT_NE(channel_mac(key, "AB", c.data(), c.size()), channel_mac(key, "A", bc.data(), bc.size()));
}

TEST(ChannelMac, ChannelNameIsCutAtLcmsLimit) {
  // LCM refuses channel names longer than 63 characters; channel_mac reads no further.
  const KeyBytes key = test_key(5);
  const Bytes body = ascii("body");
  const std::string at_limit(kMaxChannelChars, 'C');
  const std::string longer = at_limit + "EXTRA";
  const std::string shorter(kMaxChannelChars - 1, 'C');
  EXPECT_EQ(channel_mac(key, longer.c_str(), body.data(), body.size()),
            channel_mac(key, at_limit.c_str(), body.data(), body.size()));
  EXPECT_NE(channel_mac(key, shorter.c_str(), body.data(), body.size()),
            channel_mac(key, at_limit.c_str(), body.data(), body.size()));
}

TEST(ChannelMac, DiffersWhenTheKeyDiffers) {
  const Bytes body = ascii("body");
  EXPECT_NE(channel_mac(test_key(1), "EVADE_ARM", body.data(), body.size()),
            channel_mac(test_key(2), "EVADE_ARM", body.data(), body.size()));
}

// ---- mac_equal ----

TEST(MacEqual, TrueForEqualFalseForAnyDifference) {
  const Bytes body = ascii("body");
  const Mac a = channel_mac(test_key(3), "EVADE_ARM", body.data(), body.size());
  Mac b = a;
  EXPECT_TRUE(mac_equal(a.data(), b.data()));
  b[kMacBytes - 1] ^= 0x01U;  // a single bit of the last byte
  EXPECT_FALSE(mac_equal(a.data(), b.data()));
  b = a;
  b[0] ^= 0x80U;
  EXPECT_FALSE(mac_equal(a.data(), b.data()));
  const Mac other = channel_mac(test_key(4), "EVADE_ARM", body.data(), body.size());
  EXPECT_FALSE(mac_equal(a.data(), other.data()));
}

// ---- sign_encoded / mac_valid ----

TEST(SignEncoded, RoundTripsWithMacValid) {
  const KeyBytes key = test_key(21);
  Bytes msg = synthetic_message(7, 1234);
  const Bytes unsigned_copy = msg;
  ASSERT_TRUE(sign_encoded(key, "EVADE_BURN_PLAN", msg.data(), msg.size()));
  // Only the last kMacBytes were written, and they are the channel MAC of everything before.
  EXPECT_TRUE(std::equal(msg.begin(), msg.end() - static_cast<std::ptrdiff_t>(kMacBytes),
                         unsigned_copy.begin()));
  const Mac expected = channel_mac(key, "EVADE_BURN_PLAN", msg.data(), msg.size() - kMacBytes);
  EXPECT_TRUE(mac_equal(expected.data(), msg.data() + (msg.size() - kMacBytes)));
  EXPECT_TRUE(mac_valid(key, "EVADE_BURN_PLAN", msg.data(), msg.size()));
  EXPECT_FALSE(mac_valid(key, "EVADE_ARM", msg.data(), msg.size()));
  EXPECT_FALSE(mac_valid(test_key(22), "EVADE_BURN_PLAN", msg.data(), msg.size()));
}

TEST(SignEncoded, AnySingleChangedByteFailsMacValid) {
  const KeyBytes key = test_key(21);
  Bytes msg = synthetic_message(7, 1234);
  ASSERT_TRUE(sign_encoded(key, "EVADE_BURN_PLAN", msg.data(), msg.size()));
  for (std::size_t i = 0; i < msg.size(); ++i) {
    const std::uint8_t original = msg[i];
    msg[i] = static_cast<std::uint8_t>(original ^ 0xFFU);  // every bit of the byte
    EXPECT_FALSE(mac_valid(key, "EVADE_BURN_PLAN", msg.data(), msg.size())) << "byte " << i;
    msg[i] = static_cast<std::uint8_t>(original ^ 0x01U);  // a single bit of it
    EXPECT_FALSE(mac_valid(key, "EVADE_BURN_PLAN", msg.data(), msg.size())) << "bit 0 of byte " << i;
    msg[i] = original;
  }
  EXPECT_TRUE(mac_valid(key, "EVADE_BURN_PLAN", msg.data(), msg.size()));
}

TEST(SignEncoded, SmallestSignedMessageIsAccepted) {
  const KeyBytes key = test_key(9);
  Bytes msg(kMinSignedBytes, 0x5a);
  ASSERT_TRUE(sign_encoded(key, "EVADE_ARM", msg.data(), msg.size()));
  EXPECT_TRUE(mac_valid(key, "EVADE_ARM", msg.data(), msg.size()));
  TrailerView t;
  EXPECT_TRUE(read_trailer(msg.data(), msg.size(), &t));
}

TEST(SignEncoded, RefusesSizesBelowMinSignedBytes) {
  static_assert(kTrailerBytes == 44, "trailer: int32 key id, int64 ARSN, 32-byte MAC");
  static_assert(kMinSignedBytes == 52, "fingerprint and trailer");
  const KeyBytes key = test_key(9);
  for (std::size_t n : {std::size_t{0}, std::size_t{1}, kTrailerBytes, kMinSignedBytes - 1}) {
    Bytes msg(kMinSignedBytes, 0x5a);
    const Bytes before = msg;
    EXPECT_FALSE(sign_encoded(key, "EVADE_ARM", msg.data(), n)) << n;
    EXPECT_EQ(msg, before) << "sign_encoded wrote into a " << n << "-byte message";
    EXPECT_FALSE(mac_valid(key, "EVADE_ARM", msg.data(), n)) << n;
    TrailerView t;
    t.key_id = -5;
    t.arsn = -6;
    EXPECT_FALSE(read_trailer(msg.data(), n, &t)) << n;
    EXPECT_EQ(t.key_id, -5) << "read_trailer changed *out";
    EXPECT_EQ(t.arsn, -6) << "read_trailer changed *out";
    EXPECT_EQ(t.mac, nullptr) << "read_trailer changed *out";
  }
}

TEST(SignEncoded, RefusesNullPointers) {
  const KeyBytes key = test_key(9);
  TrailerView t;
  EXPECT_FALSE(sign_encoded(key, "EVADE_ARM", nullptr, 100));
  EXPECT_FALSE(mac_valid(key, "EVADE_ARM", nullptr, 100));
  EXPECT_FALSE(read_trailer(nullptr, 100, &t));
  const Bytes msg(100, 0);
  EXPECT_FALSE(read_trailer(msg.data(), msg.size(), nullptr));
}

// ---- read_trailer ----

TEST(ReadTrailer, DecodesBigEndianKeyIdAndArsnAtTheKnownOffsets) {
  Bytes msg(100, 0xEE);
  const std::size_t key_at = msg.size() - 44;
  const std::size_t arsn_at = msg.size() - 40;
  const std::uint8_t key_be[4] = {0x01, 0x02, 0x03, 0x04};
  const std::uint8_t arsn_be[8] = {0x00, 0x11, 0x22, 0x33, 0x44, 0x55, 0x66, 0x77};
  std::memcpy(msg.data() + key_at, key_be, sizeof(key_be));
  std::memcpy(msg.data() + arsn_at, arsn_be, sizeof(arsn_be));
  TrailerView t;
  ASSERT_TRUE(read_trailer(msg.data(), msg.size(), &t));
  EXPECT_EQ(t.key_id, 0x01020304);
  EXPECT_EQ(t.arsn, INT64_C(0x0011223344556677));
  EXPECT_EQ(t.mac, msg.data() + (msg.size() - kMacBytes));
}

TEST(ReadTrailer, NegativeBitPatternsAreTwosComplement) {
  Bytes msg(64, 0x00);
  const std::size_t key_at = msg.size() - 44;
  const std::size_t arsn_at = msg.size() - 40;
  // key id 0xFFFFFFFE = -2; ARSN 0x8000000000000001 = INT64_MIN + 1.
  const std::uint8_t key_be[4] = {0xFF, 0xFF, 0xFF, 0xFE};
  const std::uint8_t arsn_be[8] = {0x80, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x01};
  std::memcpy(msg.data() + key_at, key_be, sizeof(key_be));
  std::memcpy(msg.data() + arsn_at, arsn_be, sizeof(arsn_be));
  TrailerView t;
  ASSERT_TRUE(read_trailer(msg.data(), msg.size(), &t));
  EXPECT_EQ(t.key_id, -2);
  EXPECT_EQ(t.arsn, INT64_MIN + 1);

  const std::uint8_t minus_one[8] = {0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF};
  std::memcpy(msg.data() + arsn_at, minus_one, sizeof(minus_one));
  ASSERT_TRUE(read_trailer(msg.data(), msg.size(), &t));
  EXPECT_EQ(t.arsn, -1);
}

TEST(ReadTrailer, ReadsWhatSyntheticMessageWrote) {
  const Bytes msg = synthetic_message(INT32_MAX, INT64_MAX);
  TrailerView t;
  ASSERT_TRUE(read_trailer(msg.data(), msg.size(), &t));
  EXPECT_EQ(t.key_id, INT32_MAX);
  EXPECT_EQ(t.arsn, INT64_MAX);
}


// ---- derive_subkey and key_check_value (AUTH-4, KEY-1) ----

KeyBytes counting_key() {
  KeyBytes k{};
  for (std::size_t i = 0; i < k.size(); ++i) k[i] = static_cast<std::uint8_t>(i);
  return k;
}

// libsodium's own test vector (test/default/kdf.exp: master key 00..1f, context "KDF test",
// subkey id 32, 32 bytes), also reproduced with Python's hashlib.blake2b(key=master,
// salt=le64(32) || 0^8, person="KDF test" || 0^8, digest_size=32).
TEST(DeriveSubkey, MatchesLibsodiumsKdfVector) {
  const KeyBytes sub = derive_subkey(counting_key(), 32, "KDF test");
  EXPECT_EQ(to_hex(sub.data(), sub.size()),
            "154b291f11196737f8b7f491e4ca11764e0227d34f94295408a869f007aa8618");
}

TEST(DeriveSubkey, DiffersByIdContextAndMasterAndHoldsNoMasterBytes) {
  const KeyBytes master = counting_key();
  const KeyBytes a = derive_subkey(master, 1, "evadestf");
  EXPECT_EQ(a, derive_subkey(master, 1, "evadestf")) << "deterministic";
  EXPECT_NE(a, derive_subkey(master, 2, "evadestf"));
  EXPECT_NE(a, derive_subkey(master, 1, "evadestg"));
  KeyBytes other = master;
  other[31] ^= 1U;
  EXPECT_NE(a, derive_subkey(other, 1, "evadestf"));
  EXPECT_NE(a, KeyBytes{});
  const std::string sub_hex = to_hex(a.data(), a.size());
  const std::string master_hex = to_hex(master.data(), master.size());
  for (std::size_t i = 0; i + 8 <= master_hex.size(); i += 2) {
    EXPECT_EQ(sub_hex.find(master_hex.substr(i, 8)), std::string::npos) << i;
  }
}

// HMAC-SHA-256(00..1f, "evade key check value")[0, 8), computed with Python's hmac module.
TEST(KeyCheckValue, IsTheFirstEightBytesOfTheHmacOfItsLabel) {
  const KeyCheckValue kcv = key_check_value(counting_key());
  EXPECT_EQ(to_hex(kcv.data(), kcv.size()), "f158ff32821fb1bd");
  const Mac full = hmac_sha256(counting_key().data(), kKeyBytes,
                               reinterpret_cast<const std::uint8_t*>("evade key check value"), 21);
  EXPECT_TRUE(std::equal(kcv.begin(), kcv.end(), full.begin()));
}

TEST(KeyCheckValue, TellsKeysOneBitApartAndHoldsNoKeyBytes) {
  const KeyBytes k = counting_key();
  KeyBytes k2 = k;
  k2[0] ^= 0x80U;
  EXPECT_NE(key_check_value(k), key_check_value(k2));
  const KeyCheckValue kcv = key_check_value(k);
  const std::string key_hex = to_hex(k.data(), k.size());
  const std::string kcv_hex = to_hex(kcv.data(), kcv.size());
  for (std::size_t i = 0; i + 4 <= kcv_hex.size(); i += 2) {
    EXPECT_EQ(key_hex.find(kcv_hex.substr(i, 4)), std::string::npos) << kcv_hex;
  }
}

}  // namespace
}  // namespace evade::auth
