// The node's state write allocates nothing (docs/SECURITY.md AUTH-6, AUTH-4): operator new is
// counted (test/support/counting_new.hpp, in its own executable) around StateFile::save, with
// ARSNs and key states changing between saves, records of unloaded keys written back, a file and
// a symbolic link planted at the temporary name, and a save that fails: 0 allocations.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>

#include "evade/auth/key_file.hpp"
#include "evade/auth/keyring.hpp"
#include "evade/auth/state_file.hpp"
#include "support/counting_new.hpp"

namespace evade::auth {
namespace {

TEST(StateFileAllocation, SaveAllocatesNothing) {
  char tmpl[] = "/tmp/evade_auth_alloc_XXXXXX";
  ASSERT_NE(::mkdtemp(tmpl), nullptr) << std::strerror(errno);
  const std::string dir = tmpl;
  const std::string path = dir + "/node.state";
  KeyEntry tel;
  tel.id = 9;
  tel.role = KeyRole::kTelemetry;
  tel.key = generate_key(9, KeyRole::kTelemetry).key;
  const KeyRecord k1 = generate_key(1, KeyRole::kCommand);
  const KeyRecord k2 = generate_key(2, KeyRole::kCommand);
  const KeyRecord k3 = generate_key(3, KeyRole::kSensor);
  KeyRing first;
  load_into({k1, k2, k3}, &first);
  ASSERT_EQ(first.add(tel.id, tel.role, tel.key, KeyState::kActive), nullptr);
  StateFile(path, tel).init(&first, 1, 10);

  KeyRing ring;  // key 2 not loaded: its record is kept and written back
  load_into({k1, k3}, &ring);
  ASSERT_EQ(ring.add(tel.id, tel.role, tel.key, KeyState::kActive), nullptr);
  StateFile f(path, tel);
  f.load(&ring);
  ASSERT_EQ(::symlink((dir + "/victim").c_str(), (path + ".tmp").c_str()), 0);

  const long before = g_news.load();
  int failures = 0;
  for (int k = 0; k < 200; ++k) {
    (void)ring.commit(1, ArsnSlot::kCommand, 11 + k);  // advances: 11 > 10, then +1 each
    if (f.save(ring) != 0) ++failures;
  }
  const long after_saves = g_news.load();
  const std::string sub = dir + "/gone";  // a failing save: its directory removed
  ASSERT_EQ(::mkdir(sub.c_str(), 0700), 0);
  StateFile g(sub + "/node.state", tel);
  KeyRing r2 = ring;
  g.init(&r2, 1, 0);
  ASSERT_EQ(::unlink((sub + "/node.state").c_str()), 0);
  ASSERT_EQ(::rmdir(sub.c_str()), 0);
  const long before_fail = g_news.load();
  const int rc = g.save(r2);
  const long after_fail = g_news.load();

  EXPECT_EQ(after_saves - before, 0) << "operator new in StateFile::save";
  EXPECT_EQ(after_fail - before_fail, 0) << "operator new in a failing StateFile::save";
  EXPECT_EQ(failures, 0);
  EXPECT_EQ(rc, -ENOENT);
  EXPECT_EQ(f.writes(), 201);
  std::error_code ec;
  std::filesystem::remove_all(dir, ec);
}

}  // namespace
}  // namespace evade::auth
