// The CSV form of a results document: the JSON's values as the JSON writes them, one row per
// frame, text quoted only when it must be.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "core/pipeline/pipeline.h"
#include "core/report/results_csv.h"
#include "core/report/results_json.h"

using namespace tunnelmap;

namespace {
FrameResult frame(TunnelStatus status, double width_m, DimensionSource width_source) {
  FrameResult r;
  r.map.detected = status == TunnelStatus::Ok || status == TunnelStatus::Partial;
  r.map.status = status;
  r.map.width_m = width_m;
  r.map.height_m = 1.2;
  r.map.width_source = width_source;
  r.map.height_source = r.map.detected ? DimensionSource::Measured : DimensionSource::Unseen;
  r.timings_ms["total"] = 12.3456;
  return r;
}
}  // namespace

TEST(ResultsCsv, OneRowPerFrameWithTheJsonValues) {
  nlohmann::json frames = nlohmann::json::array();
  frames.push_back(detection_frame_json(0, "/data/a.png", frame(TunnelStatus::Ok, 0.8123456, DimensionSource::Measured)));
  frames.push_back(detection_frame_json(1, "/data/b, \"c\".png", frame(TunnelStatus::Partial, 0.81, DimensionSource::Context)));
  FrameResult failed = frame(TunnelStatus::MissingWall, 0.0, DimensionSource::Unseen);
  failed.map.reason = "top wall: 0 planes";
  frames.push_back(detection_frame_json(2, "/data/d.png", failed));
  nlohmann::json doc = detection_document(nlohmann::json::object(), frames, DetectionSummary(), "/data");
  doc["method"] = "ransac";
  EXPECT_EQ(detection_csv(doc),
            "index,source,method,detected,status,width_m,height_m,width_source,height_source,planes,total_ms,reason\n"
            "0,/data/a.png,ransac,1,ok,0.81235,1.2,measured,measured,0,12.346,\n"
            "1,\"/data/b, \"\"c\"\".png\",ransac,1,partial,0.81,1.2,context,measured,0,12.346,\n"
            "2,/data/d.png,ransac,0,missing_wall,,,,,0,12.346,top wall: 0 planes\n");
  // A frame's own method (the GUI's rows) wins over the document's.
  doc["frames"][1]["method"] = "qhull";
  EXPECT_NE(detection_csv(doc).find("\"/data/b, \"\"c\"\".png\",qhull,1,partial"), std::string::npos);
}

TEST(ResultsCsv, NoFramesGivesTheHeaderOnly) {
  const nlohmann::json doc = detection_document(nlohmann::json::object(), nlohmann::json::array(),
                                                DetectionSummary(), "x");
  EXPECT_EQ(detection_csv(doc),
            "index,source,method,detected,status,width_m,height_m,width_source,height_source,planes,total_ms,reason\n");
}
