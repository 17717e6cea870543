#include "sensors/openni/openni_context.h"

#include <OpenNI.h>

#include <algorithm>
#include <mutex>

#include "core/util/error.h"

namespace tunnelmap::openni2 {

void ensure_initialized() {
  static std::once_flag once;
  static std::string failure;
  std::call_once(once, [] {
    if (openni::OpenNI::initialize() != openni::STATUS_OK)
      failure = "cannot initialise: " + last_error();
  });
  if (!failure.empty()) throw InputError("OpenNI2", failure);
}

std::string last_error() {
  std::string e = openni::OpenNI::getExtendedError();
  std::replace(e.begin(), e.end(), '\n', ' ');
  std::replace(e.begin(), e.end(), '\t', ' ');
  while (!e.empty() && e.back() == ' ') e.pop_back();
  while (!e.empty() && e.front() == ' ') e.erase(e.begin());
  return e;
}

}  // namespace tunnelmap::openni2
