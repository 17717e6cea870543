#pragma once
// What the simulated OpenNI2 camera (libTunnelMapSim.so.0) and its users agree on. Plain C++,
// no OpenNI includes, so both the driver and tunnelmap_openni can use it.
//
// URI: "tunnelmap-sim://PRESET[?key=value&...]" with PRESET lab | field and keys
//   pose=K              only the preset's K-th camera pose (so one camera-frame up vector fits
//                       every frame: what `detect --up` needs for recordings)
//   disconnect_after=N  report the device unplugged after N depth frames (tests)
//   color=0             no colour sensor
//   seed=S              simulator seed
//   frames=N            length of the simulator's frame cycle (1..300, default the preset's 30;
//                       the cycle is rendered before the first frame, so short cycles start fast)
//   fps=F               frames sent per second, 1..1000 (default 30); fps=0: paced by the client,
//                       frame k+1 is sent once the client asked the pose of frame k
//                       (kCommandFramePose, which LiveDevice::read does for every frame), so no
//                       frame is lost and the camera runs as fast as its reader (soak tests); a
//                       client that never asks gets the first frame only. Either way the video
//                       mode and the frame timestamps stay the nominal 30 fps (index / 30 s).
// The driver lists "tunnelmap-sim://lab" and "tunnelmap-sim://field"; any other URI of this
// scheme is opened on demand (OpenNI2 asks the driver through tryDevice).
namespace tunnelmap::simdriver {

constexpr const char* kUriScheme = "tunnelmap-sim://";
constexpr const char* kVendor = "TunnelMap";

// Device command (openni::Device::invoke): the simulator's camera-to-world pose of a frame.
// OniFrame::frameIndex of the simulated camera is the simulator's frame index.
constexpr int kCommandFramePose = 0x54554d01;
struct FramePoseRequest {
  int frame_index = 0;            // in
  double camera_to_world[16] = {};  // out, column-major 4x4
  double world_up[3] = {0, 0, 1};   // out
};

}  // namespace tunnelmap::simdriver
