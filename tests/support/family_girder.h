#pragma once
// A girder of the whole-girder evaluation's family (core/evaluation/girder_family.h), simulated,
// with its frames detected as `map` detects them with the box-girder preset
// (resources/presets/field.json).
#include "core/evaluation/girder_family.h"
#include "core/params/parameters.h"
#include "core/pipeline/pipeline.h"
#include "core/sim/tunnel_simulator.h"

namespace tunnelmap::testing {

class FamilyGirder {
 public:
  // Girder `index` of the family drawn with `seed` (30 girders, the evaluation's ranges unless
  // others are given).
  FamilyGirder(unsigned seed, int index, const GirderRanges& ranges = {});

  const SimConfig& config() const { return config_; }
  const Parameters& params() const { return params_; }  // the box-girder preset
  const TunnelSimulator& sim() const { return sim_; }
  // Frame `frame` detected; `rendered` (when given) receives the simulator's frame.
  FrameResult detect(int frame, SimFrame* rendered = nullptr) const;

 private:
  Parameters params_;
  SimConfig config_;
  TunnelSimulator sim_;
  Pipeline pipeline_;
};

}  // namespace tunnelmap::testing
