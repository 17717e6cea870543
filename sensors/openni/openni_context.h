#pragma once
// OpenNI2 is initialised once per process (OpenNI::initialize is reference counted but its
// drivers are loaded only by the first call): everything in tunnelmap_openni goes through here.
#include <string>

namespace tunnelmap::openni2 {

// Initialises OpenNI2 on first use; InputError("OpenNI2", reason) when it cannot (no drivers).
void ensure_initialized();
// OpenNI2's last extended error, on one line ("" when none).
std::string last_error();

}  // namespace tunnelmap::openni2
