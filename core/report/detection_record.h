#pragma once
// DetectionRecord: one frame's detection as every writer and view reads it (`detect`'s JSON and
// CSV, the GUI's table, plot, status bar and exports). Typed, with unknown as an empty optional:
// JSON appears only in the writers (core/report/results_json.h, results_csv.h).
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "core/baselines/method.h"
#include "core/pipeline/pipeline.h"

namespace tunnelmap {

struct WallRecord {
  WallClass wall = WallClass::Left;
  DimensionSource source = DimensionSource::Unseen;  // measured, or inferred (context, design)
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();  // camera frame
  double offset_m = 0.0;
  std::vector<ZoneCluster> clusters;
};

// A stretch of constant cross-section a posed frame saw (TunnelPart), unknown values empty.
struct PartRecord {
  double from_m = 0.0, to_m = 0.0;
  std::optional<double> width_m, height_m;
};

struct AxisRecord {
  Eigen::Vector3d point = Eigen::Vector3d::Zero(), direction = Eigen::Vector3d::UnitZ();
  double extent_min_m = 0.0, extent_max_m = 0.0;
};

struct DetectionRecord {
  int index = 0;
  std::string source;  // the frame's file, as the reader names it
  Method method = Method::Pgc;
  int param_set = 0;  // which parameter set made it (the GUI numbers them from 1); 0 = the only one
  bool error = false;  // the frame could not be read or processed: `reason` says why
  bool detected = false;
  std::string status;  // status_name(), or "error"
  std::string reason;
  // Known values (measured in the frame, or from the context or the design: see the sources).
  std::optional<double> width_m, height_m;
  std::optional<DimensionSource> width_source, height_source;  // empty when unknown
  std::vector<WallClass> measured_walls, inferred_walls;
  std::vector<PartRecord> parts;
  std::size_t planes = 0;
  std::vector<WallRecord> walls;  // the walls found (measured or inferred), in class order
  std::optional<AxisRecord> axis;  // detected frames
  StageTimings timings_ms;

  // What the frame measured itself (never the context's or the design's values).
  std::optional<double> measured_width_m() const;
  std::optional<double> measured_height_m() const;
  bool partial() const { return detected && status == "partial"; }
  std::optional<double> total_ms() const;
};

// Frame `index`'s record from its result.
DetectionRecord detection_record(int index, const std::string& source, const FrameResult& result,
                                 Method method = Method::Pgc);
// A frame that could not be read or processed.
DetectionRecord error_record(int index, const std::string& source, const std::string& message,
                             Method method = Method::Pgc);

}  // namespace tunnelmap
