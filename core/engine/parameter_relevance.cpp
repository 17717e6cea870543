#include "core/engine/parameter_relevance.h"

#include "core/planes/grow_options.h"

namespace tunnelmap {

namespace {

bool has_prefix(const std::string& key, const char* prefix) { return key.rfind(prefix, 0) == 0; }

// The method that alone reads a key, when one does (the shared cloud and tunnel stages: none).
std::optional<Method> owning_method(const std::string& key) {
  if (has_prefix(key, "ransac.")) return Method::Ransac;
  if (has_prefix(key, "qhull.")) return Method::Qhull;
  if (has_prefix(key, "grow.") || has_prefix(key, "normals.")) return Method::Pgc;
  return std::nullopt;
}

// PG&C keys that the growing order chosen by grow.cell_px and grow.grid_step never reads.
std::string growing_order_reason(const std::string& key, const GrowOptions& grow) {
  const std::string cells = "cells of " + std::to_string(grow.cell_px) + " px";
  if (grow.cell_px > 0) {
    if (has_prefix(key, "normals."))
      return "Growing over " + cells + " fits each cell's own plane and computes no per-pixel normals; "
             "set Growing cell size to 0 to use it";
    if (key == grow_keys::neighbourhood_n.key)
      return "Growing over " + cells + " joins neighbouring cells, not an n x n pixel window; "
             "set Growing cell size to 0 to use it";
    if (key == grow_keys::grid_step.key)
      return "Growing over " + cells + " replaces the pixel grid; set Growing cell size to 0 to use it";
    return {};
  }
  if (key == grow_keys::edge_on_pass.key && grow.grid_step <= 1)
    return "A grid step of 1 grows every pixel already; the edge-on pass runs with a step of 2 or more";
  return {};
}

}  // namespace

ParameterRelevance parameter_relevance(const ParameterSpec& spec, const Parameters& params, Method method) {
  const std::optional<Method> owner = owning_method(spec.key);
  if (owner && *owner != method)
    return {Relevance::OtherMethod,
            std::string("Only ") + method_display_name(*owner) + " reads it; the method is " +
                method_display_name(method)};
  if (owner == Method::Pgc) {
    std::string reason = growing_order_reason(spec.key, grow_options(params));
    if (!reason.empty()) return {Relevance::GrowingOrder, std::move(reason)};
  }
  return {};
}

}  // namespace tunnelmap
