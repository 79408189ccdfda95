// A text output file written all or nothing: a full disk or an exception never leaves a partial
// file under the final name (as MatWriter does for .mat files).
#pragma once

#include <fstream>
#include <string>

namespace tracked_vehicle_dynamics {
namespace io {

/// Creates an empty file of a name no other writer has, next to `path`: `path` + `tag` + six
/// random letters and digits + `suffix` (O_CREAT | O_EXCL, mode 0666 less the umask, as a file
/// written in place gets), and returns its name. Each writer of `path` then stages its data
/// apart: a name made of the process id alone was shared by two threads of a process, or by
/// processes of two containers (each its own pid 1) writing one cache, whose writes then
/// interleaved in one file that a rename put in place torn.
/// Throws InputError naming `path` and the reason when it cannot be created.
std::string createTemporaryBeside(const std::string& path, const std::string& suffix = "",
                                  const std::string& tag = ".~");

/// Writes text to a temporary file next to `path` (createTemporaryBeside) (same directory, so the
/// rename is atomic on POSIX file systems); commit() checks the stream and renames it onto `path`.
/// Without a successful commit() the temporary file is removed and `path` is left as it was.
class AtomicTextFile {
 public:
  /// Throws InputError naming `path` when the temporary file cannot be created.
  explicit AtomicTextFile(const std::string& path);
  ~AtomicTextFile();
  AtomicTextFile(const AtomicTextFile&) = delete;
  AtomicTextFile& operator=(const AtomicTextFile&) = delete;

  std::ostream& stream() { return out_; }
  /// Flushes and closes the file, checks every write succeeded, renames it onto `path`. Throws
  /// InputError naming `path` (and the reason, e.g. "No space left on device") when a write or
  /// the rename failed; the temporary file is removed then.
  void commit();

  const std::string& path() const { return path_; }

 private:
  std::string path_;
  std::string temporary_;
  std::ofstream out_;
  bool committed_ = false;
};

}  // namespace io
}  // namespace tracked_vehicle_dynamics
