// The ground's anti-replay counter (docs/SECURITY.md UPLINK-1, AUTH-2; issue 40 "counters, not
// clocks"), each test in a fresh private directory beside a key file: ARSNs strictly increasing
// across objects (restarts) and per key; every number on disk before next() returns it; a missing
// file is an empty counter; raise_to raises and never lowers; a second counter on the same key
// file in another process waits 10 s and then fails with the named message, or gets the lock once
// the first one is gone; a symbolic link or file planted at the temporary name is removed and its
// target untouched; a counter file with mode 0644, a symlink, another owner, a malformed line, a
// group/other-writable directory or a symlinked key file is refused; INT64_MAX is refused by
// next() with a clear error rather than wrapping; a failed write changes nothing.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>

#include "auth_file_test_support.hpp"
#include "evade/auth/arsn_counter.hpp"
#include "evade/auth/key_file.hpp"

namespace evade::auth {
namespace {

using test::exists;
using test::mode_of;
using test::read_bytes;
using test::runtime_error_text;

class ArsnCounterTest : public test::TempDir {
 protected:
  void SetUp() override {
    TempDir::SetUp();
    key_ = path("ground.key");
    write_key_file(key_, generate_key(1, KeyRole::kCommand));
    counter_ = key_ + ".arsn";
  }
  std::string key_;
  std::string counter_;
};

// A child process that waits for a byte on go, then makes a counter on key_file: exit 0 when
// it failed with the named message after waiting at least 9.5 s, 10 + v when it got the lock and
// next(1) gave v (v < 100), other codes for anything else.
pid_t spawn_second_counter(const std::string& key_file, int go) {
  const pid_t pid = ::fork();
  if (pid != 0) return pid;
  char byte = 0;
  if (::read(go, &byte, 1) != 1) ::_exit(2);
  const auto t0 = std::chrono::steady_clock::now();
  try {
    ArsnCounter c(key_file);
    const std::int64_t v = c.next(1);
    ::_exit(v > 0 && v < 100 ? static_cast<int>(10 + v) : 3);
  } catch (const std::runtime_error& e) {
    const double waited = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const std::string want = "another evade command holds the ARSN counter of key file '" + key_file + "'";
    ::_exit(std::string(e.what()).find(want) != std::string::npos && waited >= 9.5 ? 0 : 4);
  }
  ::_exit(5);
}

int exit_code_of(pid_t pid) {
  int status = 0;
  if (::waitpid(pid, &status, 0) != pid || !WIFEXITED(status)) return -1;
  return WEXITSTATUS(status);
}

TEST_F(ArsnCounterTest, StrictlyIncreasingAcrossObjectsAndPerKey) {
  std::int64_t prev = 0;
  for (int restart = 0; restart < 5; ++restart) {
    ArsnCounter c(key_);
    EXPECT_EQ(c.existed(), restart > 0);
    for (int k = 0; k < 3; ++k) {
      const std::int64_t v = c.next(1);
      EXPECT_GT(v, prev);
      prev = v;
    }
    EXPECT_EQ(c.next(7), restart + 1) << "key 7 has a counter of its own";
  }
  EXPECT_EQ(prev, 15);
}

TEST_F(ArsnCounterTest, SurvivesReopenAsTheDocumentedText) {
  {
    ArsnCounter c(key_);
    EXPECT_EQ(c.path(), counter_);
    for (int k = 0; k < 3; ++k) (void)c.next(12);
    (void)c.next(3);
  }
  EXPECT_EQ(read_bytes(counter_), "evade-arsn 1\nkey 3 1\nkey 12 3\n");
  EXPECT_EQ(mode_of(counter_), 0600U);
  EXPECT_FALSE(exists(counter_ + ".tmp"));
  ArsnCounter c(key_);
  EXPECT_TRUE(c.existed());
  EXPECT_EQ(c.last(12), 3);
  EXPECT_EQ(c.last(3), 1);
  EXPECT_EQ(c.last(4), 0);
}

TEST_F(ArsnCounterTest, EveryNumberIsOnDiskBeforeNextReturnsIt) {
  ArsnCounter c(key_);
  for (int k = 1; k <= 5; ++k) {
    const std::int64_t v = c.next(1);
    EXPECT_EQ(read_bytes(counter_), "evade-arsn 1\nkey 1 " + std::to_string(v) + "\n");
  }
}

TEST_F(ArsnCounterTest, AMissingFileIsAnEmptyCounter) {
  ArsnCounter c(key_);
  EXPECT_FALSE(c.existed());
  EXPECT_EQ(c.last(1), 0);
  EXPECT_FALSE(exists(counter_)) << "nothing written before a number is used";
  EXPECT_EQ(c.next(1), 1);
  EXPECT_TRUE(exists(counter_));
}

TEST_F(ArsnCounterTest, RaiseToRaisesAndNeverLowers) {
  {
    ArsnCounter c(key_);
    c.raise_to(1, 500);
    EXPECT_EQ(c.last(1), 500);
    const std::string after = read_bytes(counter_);
    c.raise_to(1, 10);
    c.raise_to(1, 500);
    EXPECT_EQ(c.last(1), 500);
    EXPECT_EQ(read_bytes(counter_), after);
    EXPECT_EQ(c.next(1), 501);
  }
  ArsnCounter c(key_);
  EXPECT_EQ(c.last(1), 501);
}

TEST_F(ArsnCounterTest, ASecondCounterInAnotherProcessWaitsThenFailsWithTheNamedMessage) {
  int go[2];
  ASSERT_EQ(::pipe(go), 0);
  const pid_t pid = spawn_second_counter(key_, go[0]);  // forked before this process locks
  ASSERT_GE(pid, 0);
  ArsnCounter c(key_);
  EXPECT_EQ(c.next(1), 1);
  ASSERT_EQ(::write(go[1], "g", 1), 1);
  EXPECT_EQ(exit_code_of(pid), 0) << "0: refused after >= 9.5 s with the named message";
  EXPECT_EQ(c.next(1), 2) << "the refused command used no number";
  (void)::close(go[0]);
  (void)::close(go[1]);
}

TEST_F(ArsnCounterTest, ASecondCounterGetsTheLockOnceTheFirstIsGone) {
  int go[2];
  ASSERT_EQ(::pipe(go), 0);
  const pid_t pid = spawn_second_counter(key_, go[0]);
  ASSERT_GE(pid, 0);
  {
    ArsnCounter c(key_);
    EXPECT_EQ(c.next(1), 1);
    ASSERT_EQ(::write(go[1], "g", 1), 1);
    ::usleep(300 * 1000);  // the child is waiting for the lock now
    EXPECT_EQ(c.next(1), 2);
  }
  EXPECT_EQ(exit_code_of(pid), 13) << "10 + 3: the child waited, then used ARSN 3";
  (void)::close(go[0]);
  (void)::close(go[1]);
}

TEST_F(ArsnCounterTest, ASymbolicLinkPlantedAtTheTemporaryNameLeavesItsTargetUntouched) {
  const std::string victim = write_file("victim", "precious\n");
  ASSERT_EQ(::symlink(victim.c_str(), (counter_ + ".tmp").c_str()), 0);
  ArsnCounter c(key_);
  EXPECT_EQ(c.next(1), 1);
  EXPECT_EQ(read_bytes(victim), "precious\n");
  EXPECT_FALSE(exists(counter_ + ".tmp"));
  write_file("ground.key.arsn.tmp", "planted\n", 0644U);
  EXPECT_EQ(c.next(1), 2);
  EXPECT_EQ(read_bytes(counter_), "evade-arsn 1\nkey 1 2\n");
}

TEST_F(ArsnCounterTest, ACounterFileWithMode0644IsRefused) {
  write_file("ground.key.arsn", "evade-arsn 1\nkey 1 5\n", 0644U);
  const std::string text = runtime_error_text([&] { ArsnCounter c(key_); });
  EXPECT_NE(text.find("ARSN counter '" + counter_ + "' has mode 0644"), std::string::npos) << text;
  EXPECT_NE(text.find("chmod 600 it"), std::string::npos) << text;
}

TEST_F(ArsnCounterTest, ASymlinkedOrForeignCounterFileIsRefused) {
  const std::string real = write_file("elsewhere", "evade-arsn 1\nkey 1 5\n");
  ASSERT_EQ(::symlink(real.c_str(), counter_.c_str()), 0);
  EXPECT_NE(runtime_error_text([&] { ArsnCounter c(key_); }).find("is a symbolic link: refused"), std::string::npos);
  ASSERT_EQ(::unlink(counter_.c_str()), 0);
  if (::geteuid() != 0) return;  // another owner needs root
  write_file("ground.key.arsn", "evade-arsn 1\nkey 1 5\n");
  ASSERT_EQ(::chown(counter_.c_str(), 65534, 65534), 0);
  EXPECT_NE(runtime_error_text([&] { ArsnCounter c(key_); }).find("owned by uid 65534"), std::string::npos);
}

TEST_F(ArsnCounterTest, AMalformedCounterFileIsRefusedNamingTheLine) {
  struct Case {
    const char* text;
    const char* expect;
  };
  const Case cases[] = {
      {"", "is empty"},
      {"evade-arsn 2\nkey 1 5\n", "line 1: expected 'evade-arsn 1'"},
      {"evade-arsn 1\nkey 1 5", "was cut"},
      {"evade-arsn 1\nkey 1 -5\n", "line 2: expected 'key <id> <last ARSN>'"},
      {"evade-arsn 1\nkey 0 5\n", "line 2: expected"},
      {"evade-arsn 1\nkey 1 5 6\n", "line 2: expected"},
      {"evade-arsn 1\nkey 1  5\n", "line 2: expected"},
      {"evade-arsn 1\nkey 1 5\r\n", "line 2: expected"},
      {"evade-arsn 1\nkey 1 9223372036854775808\n", "line 2: expected"},
      {"evade-arsn 1\nkey 1 5\nkey 1 6\n", "line 3: key id 1 appears twice"},
  };
  for (const Case& c : cases) {
    write_file("ground.key.arsn", c.text);
    const std::string text = runtime_error_text([&] { ArsnCounter counter(key_); });
    EXPECT_NE(text.find(c.expect), std::string::npos) << c.text << "-> " << text;
    EXPECT_NE(text.find("remove the file to start from 0"), std::string::npos) << text;
  }
}

TEST_F(ArsnCounterTest, ADirectoryOthersCanWriteOrASymlinkedKeyFileIsRefused) {
  ASSERT_EQ(::chmod(dir_.c_str(), 0777), 0);
  EXPECT_NE(runtime_error_text([&] { ArsnCounter c(key_); }).find("group or others may write in it"),
            std::string::npos);
  ASSERT_EQ(::chmod(dir_.c_str(), 0700), 0);
  const std::string link = path("link.key");
  ASSERT_EQ(::symlink(key_.c_str(), link.c_str()), 0);
  EXPECT_NE(runtime_error_text([&] { ArsnCounter c(link); }).find("is a symbolic link: refused"), std::string::npos);
  EXPECT_THROW(ArsnCounter c(path("missing.key")), std::runtime_error);
}

TEST_F(ArsnCounterTest, NextRefusesInt64MaxRatherThanWrapping) {
  write_file("ground.key.arsn", "evade-arsn 1\nkey 1 9223372036854775806\n");
  ArsnCounter c(key_);
  EXPECT_EQ(c.next(1), INT64_MAX);
  const std::string at_max = read_bytes(counter_);
  const std::string text = runtime_error_text([&] { (void)c.next(1); });
  EXPECT_NE(text.find("key 1 has used the largest ARSN (9223372036854775807): it cannot sign again"),
            std::string::npos) << text;
  EXPECT_EQ(c.last(1), INT64_MAX);
  EXPECT_EQ(read_bytes(counter_), at_max);
  c.raise_to(1, INT64_MAX);  // already there: nothing to do
  EXPECT_EQ(c.next(2), 1) << "another key is not affected";
}

TEST_F(ArsnCounterTest, AFailedWriteThrowsNamingTheFileAndChangesNothing) {
  ArsnCounter c(key_);
  EXPECT_EQ(c.next(1), 1);
  ASSERT_EQ(::mkdir((counter_ + ".tmp").c_str(), 0700), 0);  // the temporary cannot be made
  const std::string text = runtime_error_text([&] { (void)c.next(1); });
  EXPECT_NE(text.find("ARSN counter '" + counter_ + "' cannot be written"), std::string::npos) << text;
  EXPECT_THROW(c.raise_to(1, 50), std::runtime_error);
  EXPECT_EQ(c.last(1), 1);
  EXPECT_EQ(read_bytes(counter_), "evade-arsn 1\nkey 1 1\n");
  ASSERT_EQ(::rmdir((counter_ + ".tmp").c_str()), 0);
  EXPECT_EQ(c.next(1), 2) << "the refused number was never handed out: it is used now";
}

TEST_F(ArsnCounterTest, KeyIdsOutsideTheRangeAreRefused) {
  ArsnCounter c(key_);
  EXPECT_THROW((void)c.next(0), std::invalid_argument);
  EXPECT_THROW((void)c.next(-3), std::invalid_argument);
  EXPECT_THROW(c.raise_to(0, 5), std::invalid_argument);
  EXPECT_FALSE(exists(counter_));
}

}  // namespace
}  // namespace evade::auth
