#pragma once
// An OpenNI2 recording (.oni) as a FrameSource: played back by OpenNI2's own OniFile driver,
// frame by frame on request (no real-time pacing, no looping), with random access.
// .oni files carry no camera poses: the up vector comes from --up or image-up (docs/openni.md).
// Colour frames recorded with the depth frames are attached (RGB888; JPEG-compressed when
// recorded by tunnelmap-cli record, so close to but not bit-identical with the live colour).
#include <OpenNI.h>

#include <memory>
#include <string>

#include "core/io/frame_source.h"

namespace tunnelmap::openni2 {

class OniFileSource : public FrameSource {
 public:
  // InputError(path, reason): unreadable file, no depth stream, no frames.
  OniFileSource(std::string path, ReadOptions opt);
  ~OniFileSource() override;

  std::size_t size() const override { return count_; }
  DepthFrame load(std::size_t i) const override;  // InputError for a frame that cannot be read
  std::string describe(std::size_t i) const override;
  const Intrinsics& intrinsics() const { return K_; }
  bool has_color() const { return has_color_; }

 private:
  struct Player;  // an opened recording with its streams, positioned before frame `next`
  std::unique_ptr<Player> open_player() const;
  DepthFrame read_next() const;

  std::string path_;
  mutable std::unique_ptr<Player> player_;
  std::size_t count_ = 0;
  bool has_color_ = false;
  Intrinsics K_;
};

}  // namespace tunnelmap::openni2
