#include "core/params/parameters.h"

#include "core/io/json_file.h"

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/util/atomic_file.h"
#include "core/util/error.h"

namespace tunnelmap {

namespace {
const ParameterSpec& spec_or_throw(const std::string& key) {
  const ParameterSpec* spec = find_parameter(key);
  if (!spec) throw ParameterError("unknown parameter '" + key + "' (see `tunnelmap-cli params`)");
  return *spec;
}

std::string format_number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

// Metadata keys a preset or a results file may carry beside "params".
bool is_metadata_key(const std::string& k) {
  static const char* keys[] = {"name", "description", "format", "tool", "version",
                               "method", "frames", "summary", "input"};
  for (const char* m : keys)
    if (k == m) return true;
  return false;
}
}  // namespace

Parameters::Parameters() { reset_all(); }

double Parameters::get(const std::string& key) const {
  auto it = values_.find(key);
  if (it == values_.end()) spec_or_throw(key);  // throws with a helpful message
  return it->second;
}

// One line naming the rule `values` break, or empty.
static std::string broken_rule(const ParameterRule& r, const std::map<std::string, double>& values) {
  const double a = values.at(r.a);
  switch (r.kind) {
    case ParameterRule::Kind::Less: {
      const double b = values.at(r.b);
      if (a < b) return "";
      return "parameter '" + r.a + "' = " + format_number(a) + " must be less than '" + r.b + "' = " +
             format_number(b);
    }
    case ParameterRule::Kind::Odd:
      if (static_cast<long long>(a) % 2 != 0) return "";
      return "parameter '" + r.a + "' must be odd, got " + format_number(a);
  }
  return "";
}

void Parameters::check_rules() const {
  for (const ParameterRule& r : parameter_rules()) {
    const std::string broken = broken_rule(r, values_);
    if (!broken.empty()) throw ParameterError(broken);
  }
}

void Parameters::set(const std::string& key, double value) {
  Parameters updated = *this;
  updated.set_unchecked_rules(key, value);
  // Only the rules of this key: the others held before and did not change.
  for (const ParameterRule& r : parameter_rules()) {
    if (r.a != key && r.b != key) continue;
    const std::string broken = broken_rule(r, updated.values_);
    if (!broken.empty()) throw ParameterError(broken);
  }
  values_.swap(updated.values_);
}

void Parameters::set_unchecked_rules(const std::string& key, double value) {
  const ParameterSpec& spec = spec_or_throw(key);
  if (!std::isfinite(value))
    throw ParameterError("parameter '" + key + "' must be a finite number");
  if (value < spec.min || value > spec.max)
    throw ParameterError("parameter '" + key + "' = " + format_number(value) + " is out of range [" +
                         format_number(spec.min) + ", " + format_number(spec.max) + "]" +
                         (spec.unit.empty() ? "" : " " + spec.unit));
  if (spec.integer && value != std::floor(value))
    throw ParameterError("parameter '" + key + "' must be a whole number, got " + format_number(value));
  values_[key] = value;
}

namespace {
std::pair<std::string, double> parse_assignment(const std::string& assignment) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0)
    throw ParameterError("--set expects KEY=VALUE, got '" + assignment + "'");
  const std::string key = assignment.substr(0, eq);
  const std::string text = assignment.substr(eq + 1);
  spec_or_throw(key);
  std::size_t used = 0;
  double value = 0;
  try {
    value = std::stod(text, &used);
  } catch (...) {
    used = 0;
  }
  if (used == 0 || used != text.size())
    throw ParameterError("parameter '" + key + "' expects a number, got '" + text + "'");
  return {key, value};
}
}  // namespace

void Parameters::set_from_string(const std::string& assignment) {
  const auto [key, value] = parse_assignment(assignment);
  set(key, value);
}

void Parameters::set_from_strings(const std::vector<std::string>& assignments) {
  Parameters updated = *this;  // all or nothing
  for (const std::string& a : assignments) {
    const auto [key, value] = parse_assignment(a);
    updated.set_unchecked_rules(key, value);
  }
  updated.check_rules();
  *this = updated;
}

void Parameters::reset(const std::string& key) { values_[key] = spec_or_throw(key).default_value; }

void Parameters::reset_all() {
  values_.clear();
  for (const auto& spec : parameter_table()) values_[spec.key] = spec.default_value;
}

bool Parameters::is_default(const std::string& key) const {
  return get(key) == spec_or_throw(key).default_value;
}

void Parameters::apply_json(const nlohmann::json& j, const std::string& source) {
  if (!j.is_object()) throw InputError(source, "a parameter preset must be a JSON object");
  const nlohmann::json* params = &j;
  if (j.contains("params")) {
    params = &j.at("params");
    if (!params->is_object()) throw InputError(source, "\"params\" must be a JSON object");
    for (auto it = j.begin(); it != j.end(); ++it)
      if (it.key() != "params" && !is_metadata_key(it.key()))
        throw InputError(source, "unknown key '" + it.key() + "' (parameters go inside \"params\")");
  }
  Parameters updated = *this;  // all or nothing: a bad preset leaves the values untouched
  for (auto it = params->begin(); it != params->end(); ++it) {
    if (!it.value().is_number())
      throw InputError(source, "parameter '" + it.key() + "' must be a number");
    try {
      updated.set_unchecked_rules(it.key(), it.value().get<double>());
    } catch (const ParameterError& e) {
      throw InputError(source, e.what());
    }
  }
  // Rules after the whole preset: a preset may raise a minimum above the old maximum.
  try {
    updated.check_rules();
  } catch (const ParameterError& e) {
    throw InputError(source, e.what());
  }
  *this = updated;
}

void Parameters::load_json_file(const std::string& path) {
  // read_json_file turns every JSON problem (also number overflow, "1e999") into one InputError.
  apply_json(read_json_file(path), path);
}

nlohmann::json Parameters::to_json() const {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& spec : parameter_table()) {
    const double v = get(spec.key);
    if (spec.integer)
      j[spec.key] = static_cast<long long>(v);
    else
      j[spec.key] = v;
  }
  return j;
}

void Parameters::save_json_file(const std::string& path, const std::string& name) const {
  nlohmann::json j;
  j["format"] = "tunnelmap-preset/1";
  if (!name.empty()) j["name"] = name;
  j["params"] = to_json();
  write_file_atomically(path, [&](std::ostream& out) { out << j.dump(2) << "\n"; });
}

}  // namespace tunnelmap
