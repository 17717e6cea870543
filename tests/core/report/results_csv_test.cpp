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
  DetectionDocument doc;
  doc.method = Method::Ransac;
  doc.input = "/data";
  const auto add = [&](int index, const std::string& source, const FrameResult& r) {
    doc.frames.push_back(detection_record(index, source, r, Method::Ransac));
  };
  add(0, "/data/a.png", frame(TunnelStatus::Ok, 0.8123456, DimensionSource::Measured));
  add(1, "/data/b, \"c\".png", frame(TunnelStatus::Partial, 0.81, DimensionSource::Context));
  FrameResult failed = frame(TunnelStatus::MissingWall, 0.0, DimensionSource::Unseen);
  failed.map.reason = "top wall: 0 planes";
  add(2, "/data/d.png", failed);
  doc.frames.push_back(error_record(3, "/data/e.png", "/data/e.png: not a PNG file", Method::Ransac));
  EXPECT_EQ(detection_csv(doc),
            "index,source,method,detected,status,width_m,height_m,width_source,height_source,planes,total_ms,reason\n"
            "0,/data/a.png,ransac,1,ok,0.81235,1.2,measured,measured,0,12.346,\n"
            "1,\"/data/b, \"\"c\"\".png\",ransac,1,partial,0.81,1.2,context,measured,0,12.346,\n"
            "2,/data/d.png,ransac,0,missing_wall,,,,,0,12.346,top wall: 0 planes\n"
            "3,/data/e.png,ransac,0,error,,,,,,,/data/e.png: not a PNG file\n");
  // Each row's own method (the GUI's rows can differ from the document's).
  doc.frames[1].method = Method::Qhull;
  EXPECT_NE(detection_csv(doc).find("\"/data/b, \"\"c\"\".png\",qhull,1,partial"), std::string::npos);
  // The JSON writer has the same values, and null where the CSV cell is empty.
  const nlohmann::json j = detection_document_json(doc);
  EXPECT_EQ(j["frames"][0]["width_m"].dump(), "0.81235");
  EXPECT_TRUE(j["frames"][2]["width_m"].is_null());
  EXPECT_EQ(j["frames"][1]["method"], "qhull");
  EXPECT_FALSE(j["frames"][0].contains("method"));
}

TEST(ResultsCsv, NoFramesGivesTheHeaderOnly) {
  EXPECT_EQ(detection_csv(DetectionDocument()),
            "index,source,method,detected,status,width_m,height_m,width_source,height_source,planes,total_ms,reason\n");
}

// A summary counts only measured values and says how many frames each statistic covers; a
// statistic without values is null, never 0.
TEST(ResultsJson, SummaryOfFramesWithoutAMeasuredHeightHasANullHeight) {
  DetectionSummary s;
  s.gt_width_m = 0.8;
  s.gt_height_m = 1.2;
  FrameResult a = frame(TunnelStatus::Partial, 0.81, DimensionSource::Measured);
  a.map.height_source = DimensionSource::Design;
  s.add(a);
  s.add(frame(TunnelStatus::MissingWall, 0.0, DimensionSource::Unseen));
  s.finish();
  const nlohmann::json j = summary_json(s);
  EXPECT_EQ(j["frames"], 2);
  EXPECT_EQ(j["detected"], 1);
  EXPECT_EQ(j["width_frames"], 1);
  EXPECT_EQ(j["height_frames"], 0);
  EXPECT_NEAR(j["width_mean_m"].get<double>(), 0.81, 1e-9);
  EXPECT_TRUE(j["width_std_m"].is_null());  // one value has no sample deviation
  EXPECT_TRUE(j["height_mean_m"].is_null());
  EXPECT_TRUE(j["height_abs_error_mean_m"].is_null());
  EXPECT_NEAR(j["width_abs_error_mean_m"].get<double>(), 0.01, 1e-9);
}
