// The node's authenticated state file, version 2 (include/evade/auth/state_file.hpp;
// docs/SECURITY.md AUTH-4, KEY-2; issue 40): the checked directory and state subkey, load (the
// file opened without following a link and checked on its descriptor, then state_text.cpp's
// version, MAC, parse and key checks, all before the ring changes), the first start, and the
// allocation-free save through the durable write of private_file.cpp.
#include "evade/auth/state_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "evade/auth/key_file.hpp"
#include "private_file.hpp"
#include "state_text.hpp"

namespace evade::auth {
namespace {

constexpr char kStateContext[] = "evadestf";  // crypto_kdf context: 8 characters
constexpr std::uint64_t kStateSubkeyId = 1;

}  // namespace

StateFile::StateFile(std::string path, const KeyEntry& telemetry) : path_(std::move(path)) {
  attach(telemetry);
}

StateFile::~StateFile() {
  if (dir_fd_ >= 0) (void)::close(dir_fd_);  // a directory opened for reading: nothing to lose
  wipe(mac_key_.data(), mac_key_.size());
}

StateFile::StateFile(StateFile&& o) noexcept { take(&o); }

StateFile& StateFile::operator=(StateFile&& o) noexcept {
  if (this != &o) {
    if (dir_fd_ >= 0) (void)::close(dir_fd_);  // as in the destructor
    take(&o);
  }
  return *this;
}

void StateFile::take(StateFile* o) noexcept {
  path_ = std::move(o->path_);  // std::string's move assignment: noexcept
  dir_ = std::move(o->dir_);
  name_ = std::move(o->name_);
  tmp_ = std::move(o->tmp_);
  dir_fd_ = o->dir_fd_;
  mac_key_ = o->mac_key_;
  telemetry_id_ = o->telemetry_id_;
  telemetry_kcv_ = o->telemetry_kcv_;
  kept_ = o->kept_;
  n_kept_ = o->n_kept_;
  writes_ = o->writes_;
  ready_ = o->ready_;
  o->dir_fd_ = -1;  // the moved-from object refuses load, init and save
  wipe(o->mac_key_.data(), o->mac_key_.size());
  o->ready_ = false;
}

std::string StateFile::label() const { return "auth state file '" + path_ + "'"; }

void StateFile::attach(const KeyEntry& telemetry) {
  if (telemetry.role != KeyRole::kTelemetry) {
    throw std::runtime_error(label() + ": needs the node's telemetry key, not a " +
                             role_name(telemetry.role) + " key");
  }
  if (!detail::split_path(path_, &dir_, &name_)) throw std::runtime_error(label() + ": not a file path");
  tmp_ = name_ + ".tmp";
  detail::Fd dir = detail::open_private_dir(dir_, label());
  KeyBytes sub = derive_subkey(telemetry.key, kStateSubkeyId, kStateContext);
  const bool derived = sub != KeyBytes{};
  mac_key_ = sub;
  wipe(sub.data(), sub.size());
  if (!derived) throw std::runtime_error(label() + ": libsodium could not derive the state subkey");
  telemetry_id_ = telemetry.id;
  telemetry_kcv_ = key_check_value(telemetry.key);
  dir_fd_ = dir.release();
}

void StateFile::require_attached(const char* what) const {
  if (dir_fd_ < 0) throw std::runtime_error(label() + ": " + what + " on a StateFile without a directory");
}

void StateFile::check_ring_telemetry(const KeyRing& ring) const {
  const KeyEntry* t = ring.telemetry_key();
  if (t != nullptr && (t->id != telemetry_id_ || key_check_value(t->key) != telemetry_kcv_)) {
    throw std::runtime_error(label() + ": the ring's telemetry key " + std::to_string(t->id) +
                             " is not the telemetry key the state file was opened with");
  }
}

void StateFile::load(KeyRing* ring) {
  require_attached("load");
  check_ring_telemetry(*ring);
  bool missing = false;
  const detail::Fd fd = detail::open_checked(dir_fd_, name_.c_str(), label(), &missing);
  if (missing) {
    throw std::runtime_error(label() + " does not exist: a node with command keys starts only from "
                             "its state file; on its very first start give --auth-init KEY_ID "
                             "(docs/SECURITY.md)");
  }
  detail::SecretText text(kMaxFileBytes);
  detail::read_all(fd.get(), &text, label());
  const detail::Span all{text.data(), text.size()};
  detail::state_check_version(all, label());
  const std::size_t signed_bytes = detail::state_verify_mac(all, mac_key_, label());
  const detail::ParsedState st = detail::state_parse(all, signed_bytes, label());
  if (st.telemetry_id != telemetry_id_ || st.telemetry_kcv != telemetry_kcv_) {
    throw std::runtime_error(label() + " was written for telemetry key " + std::to_string(st.telemetry_id) +
                             (st.telemetry_id == telemetry_id_ ? " with another check value" : "") +
                             ", not for the node's telemetry key " + std::to_string(telemetry_id_));
  }
  detail::state_check_keys(st, *ring, label());
  n_kept_ = 0;
  for (std::size_t i = 0; i < st.n; ++i) {
    const StateRecord& r = st.records[i];
    if (ring->find(r.id) == nullptr) kept_[n_kept_++] = r;  // at most kMaxRecords: checked
  }
  for (std::size_t i = 0; i < ring->size(); ++i) {
    const KeyEntry& e = ring->entry(i);
    if (e.role == KeyRole::kTelemetry) continue;
    const StateRecord* r = detail::state_find(st, e.id);
    (void)ring->restore(e.id, detail::state_for(st, e), r != nullptr ? r->command_arsn : 0);  // e is loaded
  }
  writes_ = st.writes;
  ready_ = true;
}

void StateFile::init(KeyRing* ring, std::int32_t active_key, std::int64_t arsn_floor) {
  require_attached("init");
  check_ring_telemetry(*ring);
  if (arsn_floor < 0) throw std::runtime_error(label() + ": the ARSN floor must be 0 or more");
  const KeyEntry* a = ring->find(active_key);
  if (a == nullptr || a->role != KeyRole::kCommand) {
    throw std::runtime_error(label() + ": key " + std::to_string(active_key) +
                             " is not a loaded command key (--auth-init names the ground's key)");
  }
  const std::string exists = label() + " already exists: --auth-init is only for a node's very first "
                                       "start (a node that has started once starts from its state file)";
  struct stat st {};
  if (::fstatat(dir_fd_, name_.c_str(), &st, AT_SYMLINK_NOFOLLOW) == 0) throw std::runtime_error(exists);
  if (errno != ENOENT) throw std::runtime_error(label() + ": " + std::strerror(errno));
  KeyRing next = *ring;
  for (std::size_t i = 0; i < next.size(); ++i) {
    const KeyEntry& e = next.entry(i);
    if (e.role == KeyRole::kCommand) {
      (void)next.restore(e.id, e.id == active_key ? KeyState::kActive : KeyState::kStandby, arsn_floor);  // loaded
    } else if (e.role == KeyRole::kSensor) {
      (void)next.restore(e.id, KeyState::kActive, 0);  // loaded
    }
  }
  ready_ = false;  // until the file is written: a failed init leaves no save over anything
  n_kept_ = 0;
  writes_ = 0;
  const int rc = write_state(next, false);
  if (rc == -EEXIST) throw std::runtime_error(exists);
  if (rc != 0) throw std::runtime_error(label() + " cannot be written: " + std::strerror(-rc));
  *ring = next;
  ready_ = true;
}

int StateFile::save(const KeyRing& ring) noexcept {
  if (!ready_ || dir_fd_ < 0) return -EINVAL;
  return write_state(ring, true);
}

int StateFile::write_state(const KeyRing& ring, bool replace) noexcept {
  if (writes_ == detail::kStateMaxCount) return -EOVERFLOW;
  char buf[kMaxFileBytes];
  detail::TextSink out{buf, sizeof(buf), 0};
  bool ok = detail::state_put_header(&out, writes_ + 1, telemetry_id_, telemetry_kcv_);
  for (std::size_t i = 0; ok && i < ring.size(); ++i) {
    const KeyEntry& e = ring.entry(i);
    if (e.role == KeyRole::kTelemetry) continue;
    ok = detail::state_put_record(&out, e.id, e.role, e.state,
                          e.arsn[static_cast<std::size_t>(ArsnSlot::kCommand)], key_check_value(e.key));
  }
  for (std::size_t i = 0; ok && i < n_kept_; ++i) {
    const StateRecord& r = kept_[i];
    if (ring.find(r.id) != nullptr) continue;  // loaded after all: the ring's state wins
    ok = detail::state_put_record(&out, r.id, r.role, r.state, r.command_arsn, r.kcv);
  }
  if (!ok || !detail::state_put_mac(&out, mac_key_)) return -ENOSPC;
  const int rc = detail::write_durably(dir_fd_, name_.c_str(), tmp_.c_str(), buf, out.n, replace);
  if (rc == 0) ++writes_;
  return rc;
}

}  // namespace evade::auth
