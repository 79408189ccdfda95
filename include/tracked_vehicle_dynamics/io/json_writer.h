// Minimal JSON writer for machine-readable CLI output (objects, arrays, numbers, strings).
// Non-finite numbers are written as null, since JSON has no NaN.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "tracked_vehicle_dynamics/types.h"

namespace tracked_vehicle_dynamics {
namespace io {

class JsonWriter {
 public:
  explicit JsonWriter(std::ostream& out) : out_(out) {}
  JsonWriter& beginObject();
  JsonWriter& endObject();
  JsonWriter& beginArray();
  JsonWriter& endArray();
  /// Key of the next value inside an object.
  JsonWriter& key(const std::string& name);
  JsonWriter& value(double v);
  JsonWriter& value(long long v);
  JsonWriter& value(int v) { return value(static_cast<long long>(v)); }
  JsonWriter& value(long v) { return value(static_cast<long long>(v)); }
  JsonWriter& value(bool v);
  JsonWriter& value(const std::string& v);
  JsonWriter& value(const char* v) { return value(std::string(v)); }
  JsonWriter& value(const Vector& v);
  JsonWriter& value(const std::vector<double>& v);
  JsonWriter& value(const Matrix& m);  ///< array of rows
  JsonWriter& value(const std::vector<std::string>& v);
  template <typename T>
  JsonWriter& field(const std::string& name, const T& v) {
    key(name);
    return value(v);
  }

  static std::string escape(const std::string& s);

 private:
  void separator();
  std::ostream& out_;
  std::vector<bool> first_;  // per open container: no element written yet
  bool after_key_ = false;
};

}  // namespace io
}  // namespace tracked_vehicle_dynamics
