// io::expandHome: a leading "~" as a shell expands it, nothing else touched.
#include <gtest/gtest.h>

#include <cstdlib>
#include <optional>
#include <string>

#include "expect_input_error.h"
#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/io/home_path.h"

namespace tvd = tracked_vehicle_dynamics;

namespace {

// Sets $HOME (unset for nullopt) for one test and puts the old value back.
class HomeVariable {
 public:
  explicit HomeVariable(const std::optional<std::string>& value) {
    if (const char* old = std::getenv("HOME"))
      old_ = old;
    if (value)
      setenv("HOME", value->c_str(), 1);
    else
      unsetenv("HOME");
  }
  ~HomeVariable() {
    if (old_)
      setenv("HOME", old_->c_str(), 1);
    else
      unsetenv("HOME");
  }
  HomeVariable(const HomeVariable&) = delete;
  HomeVariable& operator=(const HomeVariable&) = delete;

 private:
  std::optional<std::string> old_;
};

}  // namespace

TEST(ExpandHome, ALeadingTildeIsTheHomeDirectory) {
  const HomeVariable home(std::string("/home/driver"));
  EXPECT_EQ(tvd::io::expandHome("~", "cache"), "/home/driver");
  EXPECT_EQ(tvd::io::expandHome("~/", "cache"), "/home/driver/");
  EXPECT_EQ(tvd::io::expandHome("~/.ros/tvd", "cache"), "/home/driver/.ros/tvd");
}

TEST(ExpandHome, OtherPathsAreUnchanged) {
  const HomeVariable home(std::string("/home/driver"));
  for (const std::string path : {"", "/abs/~/x", "rel/x", "x~", "./~", "./~user"})
    EXPECT_EQ(tvd::io::expandHome(path, "cache"), path);
}

TEST(ExpandHome, AnotherUsersHomeIsRefusedNotTakenLiterally) {
  const HomeVariable home(std::string("/home/driver"));
  for (const std::string path : {"~root/c", "~~", "~user"})
    tvd::expectInputError(
        [&] { tvd::io::expandHome(path, "--cache-dir"); },
        {"--cache-dir '" + path + "': only a leading ~ or ~/ is expanded", "not ~user"});
}

TEST(ExpandHome, ATildeWithoutAnAbsoluteHomeIsNamed) {
  {
    const HomeVariable home(std::nullopt);
    tvd::expectInputError([] { tvd::io::expandHome("~/c", "~cache_dir"); },
                          {"~cache_dir '~/c' starts with ~", "$HOME is not set"});
    EXPECT_EQ(tvd::io::expandHome("/abs", "x"), "/abs");  // no $HOME needed
  }
  const HomeVariable home(std::string("relative"));
  tvd::expectInputError([] { tvd::io::expandHome("~", "--cache-dir"); }, {"$HOME is 'relative'"});
}
