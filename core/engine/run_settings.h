#pragma once
// What a run is made of besides its input: the parameters, the method and the camera-frame up
// the user gave. Every front end (CLI verbs, GUI, renderer, bench) fills one and hands it to the
// engine, which derives the rest from the input (a dataset's world up).
#include <Eigen/Core>
#include <optional>

#include "core/baselines/method.h"
#include "core/baselines/method_runner.h"
#include "core/io/frame_source.h"
#include "core/params/parameters.h"

namespace tunnelmap {

struct RunSettings {
  Parameters params;
  Method method = Method::Pgc;
  std::optional<Eigen::Vector3d> camera_up;  // --up; else through the pose or image-up
  int threads = 0;                           // sequence workers; 0 = all cores, 1 = serial
  bool live = false;                         // frames arrive one at a time (a camera)
};

// The world's up of posed frames: the dataset's, else +Z.
Eigen::Vector3d world_up(const FrameSource& source);

// The input set-up: the method's runner with the parameters, the user's camera up and the
// dataset's world up (the one place a front end's pipeline gets configured).
MethodRunner make_method_runner(const FrameSource& source, const RunSettings& settings);

// The same set-up for PG&C's stages alone (re-running a frame from a later stage).
Pipeline make_pipeline(const FrameSource& source, const RunSettings& settings);

// The earliest stage affected by any parameter that differs between `a` and `b`; nullopt if equal.
std::optional<Stage> first_changed_stage(const Parameters& a, const Parameters& b);

}  // namespace tunnelmap
