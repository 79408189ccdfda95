#include "tracked_vehicle_dynamics/io/atomic_file.h"

#include <stdlib.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <locale>

#include "tracked_vehicle_dynamics/error.h"

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
  std::string name = path + tag + ".XXXXXX" + suffix;
  errno = 0;
  const int fd = ::mkstemps(name.data(), static_cast<int>(suffix.size()));
  if (fd < 0)
    throw InputError("cannot write " + path + reason(errno) +
                     " (directory missing or not writable?)");
  ::close(fd);
  return name;
}

AtomicTextFile::AtomicTextFile(const std::string& path)
    : path_(path), temporary_(createTemporaryBeside(path)) {
  // Numbers as every reader of the file expects them ("1234.5", not the "1.234,5" a program's
  // std::locale::global(std::locale("de_DE.UTF-8")) would give every stream made after it).
  out_.imbue(std::locale::classic());
  errno = 0;
  out_.open(temporary_, std::ios::out | std::ios::trunc);
  if (!out_)
    throw InputError("cannot write " + path_ + reason(errno) +
                     " (directory missing or not writable?)");
}

AtomicTextFile::~AtomicTextFile() {
  if (committed_)
    return;
  out_.close();
  std::remove(temporary_.c_str());
}

void AtomicTextFile::commit() {
  errno = 0;
  out_.flush();
  const int flush_error = errno;
  out_.close();
  const int error = flush_error ? flush_error : errno;
  if (!out_) {
    std::remove(temporary_.c_str());
    committed_ = true;  // nothing left to clean up
    throw InputError("cannot write " + path_ + reason(error) + "; no file written");
  }
  if (std::rename(temporary_.c_str(), path_.c_str()) != 0) {
    const int rename_error = errno;
    std::remove(temporary_.c_str());
    committed_ = true;
    throw InputError("cannot move the written file onto " + path_ + reason(rename_error));
  }
  committed_ = true;
}

}  // namespace io
}  // namespace tracked_vehicle_dynamics
