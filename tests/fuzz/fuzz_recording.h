#pragma once
// Shared by the recording fuzz targets (MCAP, ROS 1): `data` written as a whole file named
// input<extension>, opened, listed and read through. Every message delivered must be on a
// listed topic, with its bytes present; bad input may only raise InputError.
#include <cstdint>
#include <cstdlib>
#include <string>

#include "core/recordings/recording.h"
#include "core/util/error.h"
#include "tests/fuzz/fuzz_util.h"

namespace tunnelmap::fuzz {

inline void read_recording_file(const std::uint8_t* data, std::size_t size, const std::string& name,
                                const std::string& extension) {
  const auto path = scratch_dir(name) / ("input" + extension);
  write_bytes(path, data, size);
  try {
    const auto rec = recordings::open_recording(path.string());
    std::uint64_t read = 0;
    rec->read_messages({}, [&](const recordings::MessageView& m) {
      if (m.size && !m.data) std::abort();
      if (!rec->summary().topic(m.topic)) std::abort();
      return ++read < 100000;
    });
  } catch (const InputError&) {
  }
}

}  // namespace tunnelmap::fuzz
