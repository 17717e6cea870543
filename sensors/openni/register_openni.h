#pragma once
// Makes open_input() (core/io/frame_source.h) accept ".oni" recordings. Call once at start-up
// in every executable linking tunnelmap_openni (tunnelmap-cli, the GUI).
namespace tunnelmap::openni2 {

void register_openni_inputs();

}  // namespace tunnelmap::openni2
