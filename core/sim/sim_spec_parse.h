#pragma once
// Parsers of the simulator's list-valued command-line flags (tunnelmap-cli simulate). Each
// throws a one-line ParameterError naming the flag and the bad value.
#include <string>
#include <vector>

#include "core/sim/sim_config.h"

namespace tunnelmap {

// "L:WxH,L:WxH,..." in metres, e.g. "1.5:0.84x1.30,2:0.80x1.28".
std::vector<SimSection> parse_sim_sections(const std::string& flag, const std::string& text);
// "X1,X2,..." finite numbers; `count` > 0 requires exactly that many.
std::vector<double> parse_sim_numbers(const std::string& flag, const std::string& text,
                                      std::size_t count = 0, const char* shape = "X1,X2,...");
// "FROM,TO,STOPS": start and end X in metres, a whole number of stops >= 1.
SimWalk parse_sim_walk(const std::string& flag, const std::string& text);

}  // namespace tunnelmap
