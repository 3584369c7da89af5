// The state file's save (docs/SECURITY.md AUTH-4), each test in a fresh private directory: save
// removes a file or symbolic link planted at the temporary name without touching the link's
// target, refuses before load or init, returns -errno and leaves no temporary; the directory is
// checked; the transition constructors of the node still work.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "auth_file_test_support.hpp"
#include "evade/auth/key_file.hpp"
#include "evade/auth/keyring.hpp"
#include "evade/auth/mac.hpp"
#include "evade/auth/state_file.hpp"
#include "state_file_test_fixture.hpp"

namespace evade::auth {
namespace {

using namespace test;  // the shared fixtures and helpers of test/auth

TEST_F(AuthStateFile, SaveRemovesAFilePlantedAtTheTemporaryName) {
  KeyRing r = initialized();
  write_file("node.state.tmp", "planted\n", 0644U);
  StateFile f = file();
  f.load(&r);
  ASSERT_TRUE(r.commit(1, ArsnSlot::kCommand, 1001));
  ASSERT_EQ(f.save(r), 0);
  EXPECT_FALSE(exists(state_ + ".tmp"));
  KeyRing after = ring();
  file().load(&after);
  EXPECT_EQ(arsn(after, 1), 1001);
}

// A hard link to another file planted at the temporary name: the name goes, the file it shares
// stays byte for byte.
TEST_F(AuthStateFile, SaveNeverWritesIntoAFileHardLinkedAtTheTemporaryName) {
  KeyRing r = initialized();
  const std::string victim = write_file("victim", "precious\n", 0600U);
  ASSERT_EQ(::link(victim.c_str(), (state_ + ".tmp").c_str()), 0);
  StateFile f = file();
  f.load(&r);
  ASSERT_EQ(f.save(r), 0);
  EXPECT_EQ(read_bytes(victim), "precious\n");
  EXPECT_FALSE(exists(state_ + ".tmp"));
}

TEST_F(AuthStateFile, SaveNeverWritesThroughASymbolicLinkAtTheTemporaryName) {
  KeyRing r = initialized();
  const std::string target = write_file("victim", "precious bytes\n\x01\x02", 0600U);
  const std::string before = read_bytes(target);
  ASSERT_EQ(::symlink(target.c_str(), (state_ + ".tmp").c_str()), 0);
  ASSERT_EQ(::symlink(path("not-there").c_str(), path("second.state.tmp").c_str()), 0);
  StateFile f = file();
  f.load(&r);
  ASSERT_TRUE(r.commit(1, ArsnSlot::kCommand, 1002));
  ASSERT_EQ(f.save(r), 0);
  EXPECT_EQ(read_bytes(target), before) << "the symlink's target was written";
  EXPECT_FALSE(exists(state_ + ".tmp"));
  KeyRing after = ring();
  file().load(&after);
  EXPECT_EQ(arsn(after, 1), 1002);
  // A dangling symlink at the temporary name of a first start: the target is not created.
  KeyRing r2 = ring();
  StateFile(path("second.state"), tel_).init(&r2, 1, 0);
  EXPECT_FALSE(exists(path("not-there")));
}

TEST_F(AuthStateFile, SaveWithADirectoryAtTheTemporaryNameFailsAndKeepsTheOldState) {
  KeyRing r = initialized();
  ASSERT_EQ(::mkdir((state_ + ".tmp").c_str(), 0700), 0);
  StateFile f = file();
  f.load(&r);
  const std::string old = read_bytes(state_);
  ASSERT_TRUE(r.commit(1, ArsnSlot::kCommand, 1003));
  const int rc = f.save(r);
  EXPECT_LT(rc, 0);
  EXPECT_TRUE(rc == -EISDIR || rc == -EPERM) << rc;
  EXPECT_EQ(read_bytes(state_), old);
  EXPECT_EQ(f.writes(), 1) << "a failed save counted";
}

TEST_F(AuthStateFile, FailedRenameLeavesNoTemporary) {
  KeyRing r = initialized();
  StateFile f = file();
  f.load(&r);
  ASSERT_EQ(::unlink(state_.c_str()), 0);
  ASSERT_EQ(::mkdir(state_.c_str(), 0700), 0);  // rename over a directory fails
  EXPECT_EQ(f.save(r), -EISDIR);
  EXPECT_FALSE(exists(state_ + ".tmp"));
}

TEST_F(AuthStateFile, SaveBeforeLoadOrInitIsRefusedAndWritesNothing) {
  KeyRing r = initialized();
  const std::string old = read_bytes(state_);
  StateFile f = file();
  EXPECT_EQ(f.save(r), -EINVAL);
  EXPECT_EQ(read_bytes(state_), old);
  // A refused load (here: a changed file) does not allow a save over the file either.
  std::string changed = old;
  changed[changed.find("standby")] = 'S';
  write_file("node.state", changed);
  StateFile g = file();
  EXPECT_THROW(g.load(&r), std::runtime_error);
  EXPECT_EQ(g.save(r), -EINVAL);
  EXPECT_EQ(read_bytes(state_), changed);
}

TEST_F(AuthStateFile, SaveIntoARemovedDirectoryReturnsNegativeErrno) {
  const std::string sub = path("sub");
  ASSERT_EQ(::mkdir(sub.c_str(), 0700), 0);
  KeyRing r = ring();
  StateFile f(sub + "/node.state", tel_);
  f.init(&r, 1, 0);
  ASSERT_EQ(::unlink((sub + "/node.state").c_str()), 0);
  ASSERT_EQ(::rmdir(sub.c_str()), 0);
  EXPECT_EQ(f.save(r), -ENOENT);
}

// ---- the directory, the constructor, moves ----

TEST_F(AuthStateFile, ConstructorRefusesADirectoryGroupOrOthersCanWriteAndAMissingOne) {
  for (unsigned mode : {0770U, 0707U, 0777U}) {
    ASSERT_EQ(::chmod(dir_.c_str(), mode), 0);
    const std::string text = runtime_error_text([&] { (void)file(); });
    EXPECT_NE(text.find("its directory '" + dir_ + "' has mode"), std::string::npos) << text;
    EXPECT_NE(text.find("chmod go-w it"), std::string::npos) << text;
  }
  ASSERT_EQ(::chmod(dir_.c_str(), 0755), 0);  // readable by others, writable by no one else: fine
  EXPECT_NO_THROW((void)file());
  ASSERT_EQ(::chmod(dir_.c_str(), 0700), 0);
  EXPECT_THROW((void)StateFile(path("none/node.state"), tel_), std::runtime_error);
  EXPECT_THROW((void)StateFile(dir_ + "/", tel_), std::runtime_error);
  EXPECT_THROW((void)StateFile("", tel_), std::runtime_error);
}

TEST_F(AuthStateFile, ConstructorRefusesADirectoryOfAnotherUser) {
  if (::geteuid() != 0) GTEST_SKIP() << "needs root to give a directory to another user";
  ASSERT_EQ(::chown(dir_.c_str(), 65534, 65534), 0);
  EXPECT_NE(runtime_error_text([&] { (void)file(); }).find("is owned by uid 65534"), std::string::npos);
  ASSERT_EQ(::chown(dir_.c_str(), 0, 0), 0);
}

TEST_F(AuthStateFile, LoadAndInitRefuseARingWhoseTelemetryKeyIsNotTheFilesOne) {
  (void)initialized();
  KeyEntry other = tel_;
  other.key = generate_key(kTel, KeyRole::kTelemetry).key;
  KeyRing r = ring();  // holds tel_
  const std::string text = runtime_error_text([&] { StateFile(state_, other).load(&r); });
  EXPECT_NE(text.find("the ring's telemetry key 50 is not the telemetry key the state file was opened with"),
            std::string::npos) << text;
  const std::string text2 = runtime_error_text([&] { StateFile(path("b.state"), other).init(&r, 1, 0); });
  EXPECT_NE(text2.find("is not the telemetry key the state file was opened with"), std::string::npos) << text2;
  EXPECT_FALSE(exists(path("b.state")));
}

TEST_F(AuthStateFile, ConstructorRefusesAKeyThatIsNotATelemetryKey) {
  KeyEntry cmd = tel_;
  cmd.role = KeyRole::kCommand;
  EXPECT_NE(runtime_error_text([&] { (void)StateFile(state_, cmd); }).find("needs the node's telemetry key"),
            std::string::npos);
}

TEST_F(AuthStateFile, AMovedStateFileKeepsWorkingAndTheMovedFromOneRefuses) {
  KeyRing r = initialized();
  StateFile a = file();
  a.load(&r);
  StateFile b = std::move(a);
  EXPECT_EQ(b.save(r), 0);
  EXPECT_EQ(a.save(r), -EINVAL);  // NOLINT(bugprone-use-after-move): the moved-from state is the point
  StateFile c = file();
  c = std::move(b);
  EXPECT_EQ(c.save(r), 0);
  EXPECT_EQ(c.writes(), 3);
}

}  // namespace
}  // namespace evade::auth
