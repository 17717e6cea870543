#pragma once
// The data cannot be fused within the limits: no depth in range, a span or a volume too large.
// A problem of the input, not of the command line, so the CLI reports it naming the input
// (exit 3). Still a ParameterError, because raising a fusion.* parameter may be the cure.
#include "core/util/error.h"

namespace tunnelmap {

class FusionDataError : public ParameterError {
 public:
  using ParameterError::ParameterError;
};

}  // namespace tunnelmap
