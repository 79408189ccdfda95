#include "tracked_vehicle_dynamics/io/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <locale>
#include <random>

#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/io/staged_files.h"

namespace tracked_vehicle_dynamics {
namespace io {

namespace {
// errno after a failed stream operation is what the last system call left: the best reason there
// is (ENOSPC, EFBIG, EIO), or none.
std::string reason(int error) {
  return error ? std::string(": ") + std::strerror(error) : "";
}
}  // namespace

std::string createTemporaryBeside(const std::string& path, const std::string& suffix,
                                  const std::string& tag) {
  // Not mkstemps: it creates the file 0600, which the rename would give the result (a cache or
  // output another user can no longer read). Six characters of 62 from the system's entropy: a
  // collision only retries.
  static constexpr char kAlphabet[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789";
  std::random_device entropy;
  std::uniform_int_distribution<int> pick(0, static_cast<int>(sizeof kAlphabet) - 2);
  int error = 0;
  for (int attempt = 0; attempt < 100; ++attempt) {
    std::string name = path + tag;
    for (int i = 0; i < 6; ++i)
      name += kAlphabet[pick(entropy)];
    name += suffix;
    // Created and recorded with the stopping signals held: one delivered between the two would
    // find a file its handler does not know (staged_files.h).
    const SignalsHeld held;
    const int fd = ::open(name.c_str(), O_CREAT | O_EXCL | O_WRONLY | O_CLOEXEC, 0666);
    if (fd >= 0) {
      ::close(fd);
      trackStagedFile(name);  // removed if a signal stops the process
      return name;
    }
    error = errno;
    if (error != EEXIST)
      break;
  }
  const bool directory = error == ENOENT || error == ENOTDIR || error == EACCES || error == EROFS;
  throw InputError("cannot write " + path + reason(error) +
                   (directory ? " (directory missing or not writable?)" : ""));
}

AtomicTextFile::AtomicTextFile(const std::string& path)
    : path_(path), temporary_(createTemporaryBeside(path)) {
  // Numbers as every reader of the file expects them ("1234.5", not the "1.234,5" a program's
  // std::locale::global(std::locale("de_DE.UTF-8")) would give every stream made after it).
  out_.imbue(std::locale::classic());
  errno = 0;
  out_.open(temporary_, std::ios::out | std::ios::trunc);
  if (!out_) {
    const int error = errno;
    removeStagedFile(temporary_);  // no destructor runs for a constructor that throws
    throw InputError("cannot write " + path_ + reason(error) +
                     " (directory missing or not writable?)");
  }
}

AtomicTextFile::~AtomicTextFile() {
  if (committed_)
    return;
  out_.close();
  removeStagedFile(temporary_);
}

void AtomicTextFile::commit() {
  errno = 0;
  out_.flush();
  const int flush_error = errno;
  out_.close();
  const int error = flush_error ? flush_error : errno;
  if (!out_) {
    removeStagedFile(temporary_);
    committed_ = true;  // nothing left to clean up
    throw InputError("cannot write " + path_ + reason(error) + "; no file written");
  }
  if (renameStagedFile(temporary_, path_) != 0) {
    const int rename_error = errno;
    removeStagedFile(temporary_);
    committed_ = true;
    throw InputError("cannot move the written file onto " + path_ + reason(rename_error));
  }
  committed_ = true;
}

}  // namespace io
}  // namespace tracked_vehicle_dynamics
