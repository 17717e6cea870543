#pragma once
// FrameScratch: the reused buffers of every stage for one frame at a time, owned by whoever runs
// frames (a FrameResult that is reused, a SequenceRunner worker) and passed down explicitly, so
// no stage keeps hidden per-thread state and the steady state allocates nothing per frame
// (tests/allocation). One per concurrent caller: two threads must never share one.
#include "core/normals/cloud_builder.h"
#include "core/normals/integral_normals.h"
#include "core/planes/plane_scratch.h"
#include "core/tunnel/tunnel_scratch.h"

namespace tunnelmap {

struct FrameScratch {
  CloudScratch cloud;
  NormalScratch normals;
  PlaneScratch planes;
  TunnelScratch tunnel;

  FrameScratch() = default;
  // Buffers, not a value: a copy or a move starts empty and an assignment keeps the target's own
  // buffers. So copying a FrameResult (the GUI keeps copies) copies no megabytes of scratch, and
  // a result assigned into keeps its buffers for its next frame.
  FrameScratch(const FrameScratch&) {}
  FrameScratch(FrameScratch&&) noexcept {}
  FrameScratch& operator=(const FrameScratch&) { return *this; }
  FrameScratch& operator=(FrameScratch&&) noexcept { return *this; }
};

}  // namespace tunnelmap
