#include "tracked_vehicle_dynamics/io/json_writer.h"

#include "tracked_vehicle_dynamics/io/number_text.h"
#include "tracked_vehicle_dynamics/io/utf8.h"

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
    std::string text;
    appendGeneral(text, v, 10);  // "%.10g" in every locale
    out_ << text;
  }
  return *this;
}

JsonWriter& JsonWriter::value(long long v) {
  separator();
  out_ << std::to_string(v);  // no digit grouping whatever locale the stream has
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
  for (std::size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
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
        } else if (static_cast<unsigned char>(c) < 0x80) {
          out += c;
        } else if (const std::size_t n = utf8Length(s, i); n > 0) {
          out.append(s, i, n);
          i += n - 1;
        } else {
          // A byte of no UTF-8 character (a Latin-1 file name, say): JSON text must be UTF-8,
          // so it reads as the replacement character rather than making the document invalid.
          out += "\\ufffd";
        }
    }
  }
  return out;
}

}  // namespace io
}  // namespace tracked_vehicle_dynamics
