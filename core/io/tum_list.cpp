#include "core/io/tum_list.h"

#include <charconv>
#include <cmath>
#include <cstdio>

#include "core/io/depth_png.h"
#include "core/util/error.h"

namespace tunnelmap {

namespace {

// A list's non-comment lines split into whitespace-separated fields, with their line numbers;
// checks the field count and the timestamps (first field) as it goes.
class ListScanner {
 public:
  // A UTF-8 byte order mark (as Windows editors write) is skipped, not read as part of the
  // first field.
  ListScanner(const std::string& text, std::string path, std::size_t fields, std::string layout)
      : text_(text), path_(std::move(path)), fields_(fields), layout_(std::move(layout)),
        pos_(text.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0) {}

  // Next data line's fields; false at the end.
  bool next(std::vector<std::string>& out, double& timestamp) {
    while (pos_ < text_.size()) {
      // Lines end in LF, CR LF or a lone CR (classic Mac editors).
      const std::size_t end = std::min(text_.find_first_of("\r\n", pos_), text_.size());
      const std::string line = text_.substr(pos_, end - pos_);
      pos_ = end + (text_.compare(end, 2, "\r\n") == 0 ? 2 : 1);
      ++line_;
      split(line, out);
      if (out.empty() || out[0][0] == '#') continue;
      if (out.size() != fields_)
        fail("expected '" + layout_ + "' (" + std::to_string(fields_) + " fields), got " +
             std::to_string(out.size()) + " field" + (out.size() == 1 ? "" : "s"));
      timestamp = number(out[0], "timestamp");
      if (have_previous_ && !(timestamp > previous_))
        fail("timestamp " + out[0] + " is not after the previous line's " + previous_text_ +
             " (timestamps must increase)");
      have_previous_ = true;
      previous_ = timestamp;
      previous_text_ = out[0];
      return true;
    }
    return false;
  }

  double number(const std::string& s, const char* what) const {
    double v = 0;
    const char* first = s.data();
    const char* last = s.data() + s.size();
    const auto r = std::from_chars(first, last, v);
    if (r.ec != std::errc() || r.ptr != last || !std::isfinite(v))
      fail(std::string(what) + " '" + printable(s) + "' is not a finite number");
    return v;
  }

  [[noreturn]] void fail(const std::string& problem) const {
    throw InputError(path_, "line " + std::to_string(line_) + ": " + problem);
  }
  int line() const { return line_; }

 private:
  static void split(const std::string& line, std::vector<std::string>& out) {
    out.clear();
    std::size_t i = 0;
    const auto space = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; };
    while (i < line.size()) {
      while (i < line.size() && space(line[i])) ++i;
      const std::size_t start = i;
      while (i < line.size() && !space(line[i])) ++i;
      if (i > start) out.push_back(line.substr(start, i - start));
    }
  }

  // Keeps messages one printable line whatever the file holds.
  static std::string printable(const std::string& s) {
    std::string out;
    for (unsigned char c : s.substr(0, 40)) {
      if (c >= 0x20 && c < 0x7f) {
        out += static_cast<char>(c);
      } else {
        char buf[8];
        std::snprintf(buf, sizeof buf, "\\x%02x", c);
        out += buf;
      }
    }
    return s.size() > 40 ? out + "..." : out;
  }

  const std::string& text_;
  std::string path_;
  std::size_t fields_;
  std::string layout_;
  std::size_t pos_;
  int line_ = 0;
  bool have_previous_ = false;
  double previous_ = 0;
  std::string previous_text_;
};

std::string read_list_text(const std::string& path) {
  const std::vector<std::uint8_t> bytes = read_file_bytes(path, kMaxTumListBytes);
  return std::string(bytes.begin(), bytes.end());
}

}  // namespace

std::vector<TumFileEntry> parse_tum_file_list(const std::string& text, const std::string& path) {
  ListScanner scan(text, path, 2, "timestamp path");
  std::vector<TumFileEntry> out;
  std::vector<std::string> f;
  double t = 0;
  while (scan.next(f, t)) out.push_back({t, f[1], scan.line()});
  return out;
}

std::vector<TumPoseEntry> parse_tum_groundtruth(const std::string& text, const std::string& path) {
  ListScanner scan(text, path, 8, "timestamp tx ty tz qx qy qz qw");
  std::vector<TumPoseEntry> out;
  std::vector<std::string> f;
  double t = 0;
  static const char* names[] = {"timestamp", "tx", "ty", "tz", "qx", "qy", "qz", "qw"};
  while (scan.next(f, t)) {
    double v[8];
    for (int k = 1; k < 8; ++k) v[k] = scan.number(f[k], names[k]);
    for (int k = 1; k < 4; ++k)
      if (std::abs(v[k]) > kMaxTumTranslation)
        scan.fail(std::string(names[k]) + " '" + f[k] + "' is out of range (|value| <= " + kMaxPoseTranslationText + ")");
    // File order qx qy qz qw; Eigen's constructor takes w first.
    Eigen::Quaterniond q(v[7], v[4], v[5], v[6]);
    const double norm = q.norm();
    if (!(std::abs(norm - 1.0) <= 0.01)) {
      char buf[64];
      std::snprintf(buf, sizeof buf, "%.6g", norm);
      scan.fail(std::string("quaternion (qx qy qz qw) has norm ") + buf +
                ", expected a unit quaternion (within 0.01)");
    }
    q.normalize();
    out.push_back({t, Eigen::Vector3d(v[1], v[2], v[3]), q, scan.line()});
  }
  return out;
}

std::vector<TumFileEntry> read_tum_file_list(const std::string& path) {
  return parse_tum_file_list(read_list_text(path), path);
}

std::vector<TumPoseEntry> read_tum_groundtruth(const std::string& path) {
  return parse_tum_groundtruth(read_list_text(path), path);
}

}  // namespace tunnelmap
