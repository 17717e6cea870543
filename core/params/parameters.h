#pragma once
// Parameters: a set of values for the parameter table, with range checks, the table's
// cross-field rules, and JSON presets.
#include <map>
#include <string>
#include <type_traits>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "core/params/parameter_table.h"

namespace tunnelmap {

class Parameters {
 public:
  Parameters();  // all defaults

  double get(const std::string& key) const;  // throws ParameterError for an unknown key
  int get_int(const std::string& key) const { return static_cast<int>(get(key)); }
  // A declared parameter, typed (core/*/*_options.h declare them; see parameter_key.h).
  template <class T>
  T get(const ParameterKey<T>& key) const {
    const double v = get(std::string(key.key));
    if constexpr (std::is_same_v<T, bool>)
      return v != 0;
    else
      return static_cast<T>(v);
  }
  // Range- and type-checked, and checked against the table's rules with the other values as
  // they are; throws ParameterError with a one-line message.
  void set(const std::string& key, double value);
  template <class T>
  void set(const ParameterKey<T>& key, std::common_type_t<T> value) {  // T not deduced from value
    set(std::string(key.key), static_cast<double>(value));
  }
  // "KEY=VALUE" as given to --set.
  void set_from_string(const std::string& assignment);
  // Several --set assignments, all or none: the rules are checked once all are applied, so
  // `width_min=4 width_max=6` works whatever the order.
  void set_from_strings(const std::vector<std::string>& assignments);
  void reset(const std::string& key);
  void reset_all();
  bool is_default(const std::string& key) const;

  // Presets: {"name": ..., "description": ..., "params": {"grow.angle_deg": 4, ...}}.
  // Also accepts a results JSON from `detect --json` (its "params" object). Unknown keys,
  // out-of-range values and broken rules (checked after the whole preset) throw InputError
  // naming the file; the values are then untouched.
  void load_json_file(const std::string& path);
  void apply_json(const nlohmann::json& j, const std::string& source);
  void save_json_file(const std::string& path, const std::string& name = "") const;
  nlohmann::json to_json() const;  // {"key": value, ...} in table order

  const std::map<std::string, double>& values() const { return values_; }
  bool operator==(const Parameters& o) const { return values_ == o.values_; }
  bool operator!=(const Parameters& o) const { return !(*this == o); }

 private:
  void set_unchecked_rules(const std::string& key, double value);  // range and type only
  void check_rules() const;  // throws ParameterError naming the first broken rule

  std::map<std::string, double> values_;
};

}  // namespace tunnelmap
