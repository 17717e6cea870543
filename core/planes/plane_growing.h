#pragma once
// Stage 3: PG&C plane extraction by region growing (paper section 2.1).
#include "core/frame/organized_cloud.h"
#include "core/planes/grow_options.h"  // GrowOptions
#include "core/planes/plane_segment.h"

namespace tunnelmap {

struct PlaneScratch;  // core/planes/plane_scratch.h

// Into `out`, reusing its buffers and those of `scratch` (no allocation per frame in the
// steady state). One scratch per concurrent caller.
void extract_planes(const OrganizedCloud& cloud, const GrowOptions& options, PlaneSegments& out,
                    PlaneScratch& scratch);
// The same with scratch of its own: allocates it on every call (one-off frames, tests).
void extract_planes(const OrganizedCloud& cloud, const GrowOptions& options, PlaneSegments& out);
PlaneSegments extract_planes(const OrganizedCloud& cloud, const GrowOptions& options);

}  // namespace tunnelmap
