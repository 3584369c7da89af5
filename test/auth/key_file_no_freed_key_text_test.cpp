// Key files (docs/SECURITY.md KEY-1): no heap block is freed still holding key text, on success
// or on any error. freed_memory_scan.hpp replaces operator new and delete in auth_test: this is
// the one file of it that includes it.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "auth_file_test_support.hpp"
#include "evade/auth/key_file.hpp"
#include "evade/auth/keyring.hpp"
#include "key_file_test_support.hpp"
#include "freed_memory_scan.hpp"


namespace evade::auth {
namespace {

using namespace test;  // the shared fixtures and helpers of test/auth
// after wiping the key text and key bytes out of them.
TEST_F(KeyFile, NoFreedBufferHoldsKeyTextOnSuccessOrOnAnyError) {
  const KeyRecord k = generate_key(4, KeyRole::kCommand);
  const std::string hex = to_hex(k.key);
  std::vector<std::string> files;
  files.push_back(write_file("good.key", "key 4 command " + hex + "\n"));
  files.push_back(write_file("open.key", "key 4 command " + hex + "\n", 0644U));
  files.push_back(write_file("crlf.key", "key 4 command " + hex + "\r\n"));
  files.push_back(write_file("swap.key", "key 4 " + hex + " command\n"));
  files.push_back(write_file("upper.key", "key 4 command " + test::upper(hex) + "\n"));
  files.push_back(write_file("dup.key", "key 4 command " + hex + "\nkey 4 sensor " + hex + "\n"));
  files.push_back(write_file("extra.key", "key 4 command " + hex + " " + hex + "\n"));
  files.push_back(write_file("later.key", "key 4 command " + hex + "\nkey 5 sensor 00\n"));
  const std::vector<std::string> needles = test::secret_needles(k.key.data(), k.key.size());
  for (const std::string& f : files) {
    long hits = 0;
    long scanned = 0;
    bool threw = false;
    {
      test::FreedMemoryScan scan(needles);
      try {
        std::vector<KeyRecord> r = read_key_file(f);
        r.push_back(r.at(0));  // a copy and a reallocation: the moved-from storage too
      } catch (const std::runtime_error&) {
        threw = true;
      }
      scan.stop();
      hits = scan.hits();
      scanned = scan.scanned();
    }
    EXPECT_EQ(hits, 0) << f << (threw ? " (refused)" : " (read)");
    EXPECT_GT(scanned, 0) << f << ": the scan saw no freed block";
    EXPECT_EQ(threw, f != files[0]) << f;
  }
}

// The scan above can fail: a freed string that still holds key text is found.
TEST(FreedMemoryScan, FindsKeyTextLeftInAFreedBlock) {
  const KeyRecord k = generate_key(4, KeyRole::kCommand);
  const std::vector<std::string> needles = test::secret_needles(k.key.data(), k.key.size());
  const std::string hex = to_hex(k.key);
  long hits = 0;
  {
    test::FreedMemoryScan scan(needles);
    { const std::string copy = "prefix " + hex.substr(10, 20); }  // freed unwiped
    scan.stop();
    hits = scan.hits();
  }
  EXPECT_GE(hits, 1) << "a string freed still holding key text was not found";
}

}  // namespace
}  // namespace evade::auth
