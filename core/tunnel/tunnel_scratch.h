#pragma once
// The buffers of the tunnel stage (detect_tunnel), owned by the caller: one TunnelScratch per
// caller that detects concurrently (Pipeline keeps one in each FrameResult, SequenceRunner one
// per worker). With them and a reused TunnelMap, detecting frame after frame allocates nothing
// in the steady state (tests/allocation).
#include <cstddef>
#include <vector>

#include "core/tunnel/normal_outliers.h"
#include "core/tunnel/template_fit.h"
#include "core/tunnel/zone_clustering.h"

namespace tunnelmap {

struct TunnelScratch {
  std::vector<std::size_t> members;     // the planes of one wall class
  std::vector<WeightedNormal> normals;  // their normals
  NormalClassStats stats;
  OutlierScratch outliers;
  TemplateFrame frame;
  std::vector<ZonePosition> positions;  // one wall's zone positions
  ZoneClusterScratch zones;
};

}  // namespace tunnelmap
