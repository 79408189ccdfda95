// The staged (temporary) files of a process's atomic writers, removed when a signal stops it.
//
// Every output is written under a temporary name beside its own and renamed into place
// (atomic_file.h): a run that fails leaves the old file as it was. A run stopped by Ctrl-C, by
// roslaunch or by a play_track_bag.sh that is itself stopped (SIGINT, SIGTERM, SIGHUP) left the
// temporary behind, "road.bag.~Ab3xYz" of tens of MB beside the bag. A program that installs
// removeStagedFilesOnSignals() removes them before it dies of the signal.
#pragma once

#include <signal.h>

#include <cstddef>
#include <string>

namespace tracked_vehicle_dynamics {
namespace io {

/// Records `path` as staged (createTemporaryBeside does). Thread-safe. A path of more than 4095
/// bytes, or one beyond the 64 staged at once, is not recorded (it is then left on a signal, as
/// before).
void trackStagedFile(const std::string& path);
/// Forgets `path` (renamed into place or removed). Thread-safe; an unknown path is ignored.
void untrackStagedFile(const std::string& path);
/// std::remove(path), and forgets it.
void removeStagedFile(const std::string& path);
/// std::rename(path, to); forgets `path` when it succeeds. Returns rename's result (errno set).
int renameStagedFile(const std::string& path, const std::string& to);
/// The number of files recorded now (tests).
std::size_t stagedFileCount();

/// Holds SIGINT, SIGTERM and SIGHUP back in this thread while it lives (they are delivered when
/// it ends): around the creation and recording of a staged file, so a signal between the two
/// cannot leave a file the handler does not know (createTemporaryBeside).
class SignalsHeld {
 public:
  SignalsHeld();
  ~SignalsHeld();
  SignalsHeld(const SignalsHeld&) = delete;
  SignalsHeld& operator=(const SignalsHeld&) = delete;

 private:
  sigset_t saved_;
};

/// Installs handlers of SIGINT, SIGTERM and SIGHUP that remove every staged file and then end
/// the process by the signal as its default action does (a shell sees status 128 + n), and
/// ignores SIGXFSZ, so a write beyond a file size limit (ulimit -f) fails with EFBIG, which the
/// writers report naming the file, instead of ending the process with its staged files left.
/// For a program's main(): a handler another library installed for these signals is replaced;
/// an ignored signal stays ignored.
void removeStagedFilesOnSignals();

}  // namespace io
}  // namespace tracked_vehicle_dynamics
