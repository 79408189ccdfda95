#include "tracked_vehicle_dynamics/io/json_writer.h"

#include <cmath>
#include <cstdio>

namespace tracked_vehicle_dynamics {
namespace io {

void JsonWriter::separator() {
  if (after_key_) {
    after_key_ = false;
    return;
  }
  if (!first_.empty()) {
    if (!first_.back())
      out_ << ",";
    first_.back() = false;
  }
}

JsonWriter& JsonWriter::beginObject() {
  separator();
  out_ << "{";
  first_.push_back(true);
  return *this;
}

JsonWriter& JsonWriter::endObject() {
  first_.pop_back();
  out_ << "}";
  if (first_.empty())
    out_ << "\n";
  return *this;
}

JsonWriter& JsonWriter::beginArray() {
  separator();
  out_ << "[";
  first_.push_back(true);
  return *this;
}

JsonWriter& JsonWriter::endArray() {
  first_.pop_back();
  out_ << "]";
  return *this;
}

JsonWriter& JsonWriter::key(const std::string& name) {
  separator();
  out_ << "\"" << escape(name) << "\":";
  after_key_ = true;
  return *this;
}

JsonWriter& JsonWriter::value(double v) {
  separator();
  if (!std::isfinite(v)) {
    out_ << "null";
  } else {
    char buf[32];
    std::snprintf(buf, sizeof(buf), "%.10g", v);
    out_ << buf;
  }
  return *this;
}

JsonWriter& JsonWriter::value(long long v) {
  separator();
  out_ << v;
  return *this;
}

JsonWriter& JsonWriter::value(bool v) {
  separator();
  out_ << (v ? "true" : "false");
  return *this;
}

JsonWriter& JsonWriter::value(const std::string& v) {
  separator();
  out_ << "\"" << escape(v) << "\"";
  return *this;
}

JsonWriter& JsonWriter::value(const Vector& v) {
  beginArray();
  for (Eigen::Index i = 0; i < v.size(); ++i)
    value(v(i));
  return endArray();
}

JsonWriter& JsonWriter::value(const std::vector<double>& v) {
  beginArray();
  for (const double x : v)
    value(x);
  return endArray();
}

JsonWriter& JsonWriter::value(const Matrix& m) {
  beginArray();
  for (Eigen::Index i = 0; i < m.rows(); ++i)
    value(Vector(m.row(i).transpose()));
  return endArray();
}

JsonWriter& JsonWriter::value(const std::vector<std::string>& v) {
  beginArray();
  for (const auto& s : v)
    value(s);
  return endArray();
}

std::string JsonWriter::escape(const std::string& s) {
  std::string out;
  out.reserve(s.size());
  for (char c : s) {
    switch (c) {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\t':
        out += "\\t";
        break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof(buf), "\\u%04x", c);
          out += buf;
        } else {
          out += c;
        }
    }
  }
  return out;
}

}  // namespace io
}  // namespace tracked_vehicle_dynamics
