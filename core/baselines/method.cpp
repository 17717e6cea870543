#include "core/baselines/method.h"

#include <sstream>

#include "core/util/error.h"

namespace tunnelmap {

const char* method_name(Method m) {
  switch (m) {
    case Method::Pgc: return "pgc";
    case Method::Ransac: return "ransac";
    case Method::Qhull: return "qhull";
  }
  return "pgc";
}

const char* method_display_name(Method m) {
  switch (m) {
    case Method::Pgc: return "PG&C";
    case Method::Ransac: return "RANSAC & LSE";
    case Method::Qhull: return "Qhull";
  }
  return "PG&C";
}

Method parse_method(const std::string& name) {
  if (name == "pgc") return Method::Pgc;
  if (name == "ransac") return Method::Ransac;
  if (name == "qhull") return Method::Qhull;
  throw ParameterError("unknown method '" + name + "' (expected pgc, ransac or qhull)");
}

std::vector<Method> parse_methods(const std::string& list) {
  std::vector<Method> out;
  std::stringstream ss(list);
  std::string item;
  while (std::getline(ss, item, ','))
    if (!item.empty()) out.push_back(parse_method(item));
  if (out.empty()) throw ParameterError("empty method list (expected e.g. pgc,ransac,qhull)");
  return out;
}

}  // namespace tunnelmap
