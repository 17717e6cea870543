#include "tests/support/family_girder.h"

#include <string>

#include "core/util/build_paths.h"

namespace tunnelmap::testing {

namespace {

Parameters field_preset() {
  Parameters params;
  params.load_json_file(std::string(TUNNELMAP_SOURCE_DIR) + "/resources/presets/field.json");
  return params;
}

}  // namespace

FamilyGirder::FamilyGirder(unsigned seed, int index, const GirderRanges& ranges)
    : params_(field_preset()),
      config_(draw_girders(30, seed, ranges)[static_cast<std::size_t>(index)].config),
      sim_(config_),
      pipeline_(params_) {}

FrameResult FamilyGirder::detect(int frame, SimFrame* rendered) const {
  SimFrame f = sim_.render(frame);
  FrameResult r;
  pipeline_.run(f.frame, r);
  if (rendered) *rendered = std::move(f);
  return r;
}

}  // namespace tunnelmap::testing
