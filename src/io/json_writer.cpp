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

namespace {

// The length of the well-formed UTF-8 sequence at s[i] (RFC 3629: no overlong forms, no
// surrogates, nothing above U+10FFFF), 0 when there is none.
std::size_t utf8Length(const std::string& s, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char b = byte(i);
  std::size_t n = 0;
  unsigned char low = 0x80, high = 0xBF;  // the second byte's range
  if (b >= 0xC2 && b <= 0xDF) {
    n = 2;
  } else if (b >= 0xE0 && b <= 0xEF) {
    n = 3;
    low = b == 0xE0 ? 0xA0 : 0x80;
    high = b == 0xED ? 0x9F : 0xBF;
  } else if (b >= 0xF0 && b <= 0xF4) {
    n = 4;
    low = b == 0xF0 ? 0x90 : 0x80;
    high = b == 0xF4 ? 0x8F : 0xBF;
  } else {
    return 0;
  }
  if (i + n > s.size() || byte(i + 1) < low || byte(i + 1) > high)
    return 0;
  for (std::size_t k = 2; k < n; ++k)
    if (byte(i + k) < 0x80 || byte(i + k) > 0xBF)
      return 0;
  return n;
}

}  // namespace

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
