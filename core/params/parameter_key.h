#pragma once
// One parameter's declaration, written once beside the module that reads it (e.g.
// core/planes/grow_options.h): key, unit, default, range, step, stage, label, description, and
// its C++ type. The option structs take their member defaults from these constants, the
// *_options(Parameters) functions read values through them (Parameters::get(key)), and the
// global table (parameter_table.cpp) is assembled from them. No key string lives anywhere else.
#include <string>
#include <type_traits>
#include <vector>

namespace tunnelmap {

// The first pipeline stage a parameter affects: changing it re-runs that stage and later ones.
// Fusion: multi-frame TSDF fusion (`fuse`), after the per-frame stages; changing it re-runs none.
// Map: the station map of the whole tunnel (`map`, `fuse --map`); changing it re-runs none.
// Baselines: the paper's comparison methods (R&L, Qhull), which always run the whole frame.
enum class Stage { Cloud = 0, Normals = 1, Planes = 2, Tunnel = 3, Fusion = 4, Map = 5, Baselines = 6 };
const char* stage_name(Stage s);

struct ParameterSpec {
  std::string key;          // "grow.angle_deg"
  std::string unit;         // "deg", "mm", "m", "m2", "px", "points", "" (dimensionless)
  double default_value;
  double min;
  double max;
  double step;
  bool integer;             // whole numbers only
  Stage stage;
  std::string label;        // short human name for the GUI
  std::string description;  // one line, used as tooltip and in `params`
};

// T is double, int or bool (int and bool are whole numbers in the table; bool is 0 or 1).
template <class T>
struct ParameterKey {
  static_assert(std::is_same_v<T, double> || std::is_same_v<T, int> || std::is_same_v<T, bool>,
                "a parameter is a double, an int or a bool");
  const char* key;
  const char* unit;
  T default_value;
  double min, max, step;
  Stage stage;
  const char* label;
  const char* description;

  ParameterSpec spec() const {
    return {key, unit, static_cast<double>(default_value), min, max, step,
            !std::is_same_v<T, double>, stage, label, description};
  }
};

// A rule between values that a range cannot express. Checked by Parameters::set against the
// current other value, and after a whole preset or --set list is applied.
struct ParameterRule {
  enum class Kind { Less, Odd };
  Kind kind;
  std::string a, b;  // Less: a < b; Odd: a is odd (b empty)
};

template <class T>
ParameterRule less_than(const ParameterKey<T>& a, const ParameterKey<T>& b) {
  return {ParameterRule::Kind::Less, a.key, b.key};
}
inline ParameterRule odd(const ParameterKey<int>& a) { return {ParameterRule::Kind::Odd, a.key, ""}; }

// A module's declarations in table order, and its rules.
struct ParameterGroup {
  std::vector<ParameterSpec> specs;
  std::vector<ParameterRule> rules;
};

// Table values in millimetres, options in metres: the one conversion both use.
constexpr double mm_to_m(double mm) { return mm / 1000.0; }

}  // namespace tunnelmap
