#pragma once
// Parameters: a set of values for the parameter table, with range checks and JSON presets.
#include <map>
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "core/params/parameter_table.h"

namespace tunnelmap {

class Parameters {
 public:
  Parameters();  // all defaults

  double get(const std::string& key) const;  // throws ParameterError for an unknown key
  int get_int(const std::string& key) const { return static_cast<int>(get(key)); }
  // Range- and type-checked; throws ParameterError with a one-line message.
  void set(const std::string& key, double value);
  // "KEY=VALUE" as given to --set.
  void set_from_string(const std::string& assignment);
  void reset(const std::string& key);
  void reset_all();
  bool is_default(const std::string& key) const;

  // Presets: {"name": ..., "description": ..., "params": {"grow.angle_deg": 4, ...}}.
  // Also accepts a results JSON from `detect --json` (its "params" object). Unknown keys and
  // out-of-range values throw InputError naming the file.
  void load_json_file(const std::string& path);
  void apply_json(const nlohmann::json& j, const std::string& source);
  void save_json_file(const std::string& path, const std::string& name = "") const;
  nlohmann::json to_json() const;  // {"key": value, ...} in table order

  const std::map<std::string, double>& values() const { return values_; }
  bool operator==(const Parameters& o) const { return values_ == o.values_; }
  bool operator!=(const Parameters& o) const { return !(*this == o); }

 private:
  std::map<std::string, double> values_;
};

}  // namespace tunnelmap
