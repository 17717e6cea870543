#include "core/sim/sim_spec_parse.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>

#include "core/util/error.h"

namespace tunnelmap {

namespace {

[[noreturn]] void fail(const std::string& flag, const std::string& problem) {
  throw ParameterError("simulate: " + flag + ": " + problem);
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t") - b + 1);
}

std::vector<std::string> split(const std::string& text, char sep) {
  std::vector<std::string> parts;
  std::string::size_type start = 0;
  for (;;) {
    const auto end = text.find(sep, start);
    parts.push_back(trim(text.substr(start, end == std::string::npos ? end : end - start)));
    if (end == std::string::npos) return parts;
    start = end + 1;
  }
}

// The whole string must be one finite number.
bool to_number(const std::string& s, double& out) {
  if (s.empty()) return false;
  char* end = nullptr;
  errno = 0;
  out = std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size() && errno == 0 && std::isfinite(out);
}

double number(const std::string& flag, const std::string& s, const std::string& what) {
  double v = 0.0;
  if (!to_number(s, v)) fail(flag, what + " '" + s + "' is not a number");
  return v;
}

}  // namespace

std::vector<SimSection> parse_sim_sections(const std::string& flag, const std::string& text) {
  std::vector<SimSection> out;
  for (const std::string& item : split(text, ',')) {
    const auto colon = item.find(':');
    const auto x = item.find_first_of("xX", colon == std::string::npos ? 0 : colon);
    if (colon == std::string::npos || x == std::string::npos)
      fail(flag, "'" + item + "' is not LENGTH:WIDTHxHEIGHT (metres, e.g. 1.5:0.84x1.30)");
    SimSection s;
    const std::string n = "section " + std::to_string(out.size() + 1);
    s.length_m = number(flag, trim(item.substr(0, colon)), n + " length");
    s.width_m = number(flag, trim(item.substr(colon + 1, x - colon - 1)), n + " width");
    s.height_m = number(flag, trim(item.substr(x + 1)), n + " height");
    if (s.length_m <= 0.0)
      fail(flag, n + " length " + trim(item.substr(0, colon)) + " must be > 0");
    out.push_back(s);
  }
  return out;
}

std::vector<double> parse_sim_numbers(const std::string& flag, const std::string& text,
                                      std::size_t count, const char* shape) {
  const std::vector<std::string> parts = split(text, ',');
  if (count > 0 && parts.size() != count)
    fail(flag, "expected " + std::string(shape) + ", got '" + text + "'");
  std::vector<double> out;
  for (const std::string& p : parts) {
    double v = 0.0;
    if (!to_number(p, v)) fail(flag, "'" + p + "' is not a number (expected " + shape + ")");
    out.push_back(v);
  }
  return out;
}

SimWalk parse_sim_walk(const std::string& flag, const std::string& text) {
  const std::vector<double> v = parse_sim_numbers(flag, text, 3, "FROM,TO,STOPS");
  if (v[2] != std::floor(v[2]) || v[2] < 1.0 || v[2] > 100000.0)
    fail(flag, "STOPS must be a whole number from 1 to 100000, got '" + split(text, ',')[2] + "'");
  SimWalk w;
  w.start_x_m = v[0];
  w.end_x_m = v[1];
  w.stops = static_cast<int>(v[2]);
  return w;
}

}  // namespace tunnelmap
