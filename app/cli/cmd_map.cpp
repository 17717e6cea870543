// `tunnelmap-cli map DATASET`: the whole tunnel as a station profile along its axis, in the world
// frame of the dataset's poses (explicit, else forward kinematics): width and height per station,
// sections of constant cross-section, deviation from the design, poses to rescan; as JSON, CSV,
// a sectioned PLY map and a PDF inspection report.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>

#include "app/cli/commands.h"
#include "app/cli/input_options.h"
#include "app/cli/output_options.h"
#include "core/export/map_ply.h"
#include "core/fusion/fusion_options.h"
#include "core/io/dataset.h"
#include "core/kinematics/frame_pose.h"
#include "core/kinematics/robot_json.h"
#include "core/mapping/dataset_mapping.h"
#include "core/mapping/slam_options.h"
#include "core/mapping/rescan_stretches.h"
#include "core/mapping/station_map_builder.h"
#include "core/report/girder_json.h"
#include "core/report/pose_refinement_json.h"
#include "core/report/results_json.h"
#include "core/report/station_map_json.h"
#include "core/util/atomic_file.h"
#include "core/util/error.h"
#ifdef TUNNELMAP_HAVE_REPORT
#include "ui/report/map_report.h"
#endif

namespace tunnelmap::cli {

namespace {

struct MapOptions {
  InputOptions in;
  std::optional<double> station_step, tolerance_mm;
  std::string design;  // "WxH"
  std::string json_path, csv_path, ply_path, report_path, diaphragms_csv_path;
  bool no_pose_refinement = false;
  bool quiet = false;
};

// "0.82x1.30" -> width, height (metres).
std::pair<double, double> parse_design(const std::string& text) {
  const auto x = text.find_first_of("xX");
  double w = 0, h = 0;
  std::size_t used_w = 0, used_h = 0;
  try {
    if (x != std::string::npos) {
      w = std::stod(text.substr(0, x), &used_w);
      h = std::stod(text.substr(x + 1), &used_h);
    }
  } catch (...) {
    used_w = used_h = 0;
  }
  if (x == std::string::npos || used_w != x || used_h != text.size() - x - 1 || !(w > 0) || !(h > 0))
    throw ParameterError("--design expects WIDTHxHEIGHT in metres, e.g. 0.82x1.30, got '" + text + "'");
  return {w, h};
}

Parameters map_parameters(const MapOptions& o) {
  Parameters p = o.in.parameters();
  // The flags are parameter-table keys (presets may carry a design): range checks included.
  if (o.station_step) p.set(map_keys::station_step_m, *o.station_step);
  if (o.tolerance_mm) p.set(map_keys::tolerance_mm, *o.tolerance_mm);
  if (!o.design.empty()) {
    const auto [w, h] = parse_design(o.design);
    p.set(tunnel_keys::design_width_m, w);
    p.set(tunnel_keys::design_height_m, h);
  }
  return p;
}

// Per pose group, the correction of its pose against the map (null when not refined).
void add_refinement(nlohmann::json& doc, const PoseRefinement& r) {
  doc["pose_refinement"] = pose_refinement_json(r);
  for (nlohmann::json& p : doc["poses"]) {
    p["refinement"] = nullptr;
    if (!r.ran) continue;
    for (const PoseCorrection& c : r.groups)
      if (c.group == p["group"].get<int>())
        p["refinement"] = {{"rotation_deg", c.rotation_deg},
                           {"translation_mm", c.translation_mm},
                           {"constrained", c.constrained},
                           {"degenerate", c.degenerate}};
  }
}

// The stretches whose size no frame measured; those that hold a joint line by line.
void print_rescan(const StationMap& m) {
  const std::vector<RescanStretch> stretches = rescan_stretches(m);
  if (stretches.empty()) return;
  double metres[2] = {0.0, 0.0};  // width, height
  for (const RescanStretch& r : stretches)
    metres[r.dimension == StationDimension::Width ? 0 : 1] += r.to_m - r.from_m;
  std::printf("rescan: %zu stretch(es) where no frame measured the width (%.1f m in all) or the height (%.1f m)\n",
              stretches.size(), metres[0], metres[1]);
  for (const RescanStretch& r : stretches)
    if (r.joint_inside) std::printf("rescan %.2f to %.2f m: %s\n", r.from_m, r.to_m, r.reason.c_str());
}

void print_summary(const StationMap& m, const PoseRefinement& refinement, const MappingNotes& notes,
                   double detect_ms, double map_ms, int frames) {
  std::printf("map: %zu stations of %.2f m over %.2f m, %zu section(s), %d of %d frames used\n",
              m.stations.size(), m.options.station_step_m,
              m.sections.empty() ? 0.0 : m.sections.back().to_m - m.sections.front().from_m,
              m.sections.size(), m.frames_used, m.frames);
  for (std::size_t i = 0; i < m.sections.size(); ++i) {
    const Section& s = m.sections[i];
    std::printf("section %zu: %.2f to %.2f m, width %.4f m, height %.4f m, %d frames\n", i + 1,
                s.from_m, s.to_m, s.width_m, s.height_m, s.frames);
  }
  const auto off = m.out_of_tolerance();
  if (m.options.design_width_m || m.options.design_height_m)
    std::printf("design %.3f x %.3f m, tolerance %.1f mm: %zu station(s) out of tolerance\n",
                m.options.design_width_m.value_or(NAN), m.options.design_height_m.value_or(NAN),
                m.options.tolerance_mm, off.size());
  for (const PoseGroupStatus& p : m.poses)
    if (p.rescan)
      std::printf("pose %d (frames %d-%d): %s\n", p.group, p.frames.front(), p.frames.back(),
                  p.message.c_str());
  print_rescan(m);
  for (const std::string& line : notes.unchecked_poses) std::printf("%s\n", line.c_str());
  for (const std::string& line : notes.plates_beyond_range) std::printf("%s\n", line.c_str());
  if (refinement.ran && refinement.given_poses_kept) {
    std::printf("poses kept as given: the structure agrees with them within its noise (chi-square gain %.1f, "
                "threshold %.1f)\n", refinement.evidence.chi2_gain, refinement.evidence.threshold);
  } else if (refinement.ran) {
    double deg = 0.0, mm = 0.0;
    for (const PoseCorrection& c : refinement.groups)
      deg = std::max(deg, c.rotation_deg), mm = std::max(mm, c.translation_mm);
    std::printf("poses refined against the map: %zu group(s), largest correction %.2f deg, %.1f mm\n",
                refinement.groups.size(), deg, mm);
  }
  std::printf("time: detection %.1f ms/frame, map %.2f ms/frame\n",
              frames ? detect_ms / frames : 0.0, frames ? map_ms / frames : 0.0);
}


void run(const MapOptions& o, CliContext& ctx) {
  const Parameters params = map_parameters(o);
  Pipeline pipeline = o.in.pipeline();
  pipeline.set_params(params);
  // Fail now, not after the work.
  check_outputs({o.in.input, o.in.params_file},
                {o.json_path, o.csv_path, o.ply_path, o.report_path, o.diaphragms_csv_path});
  const DatasetInput input(o.in);  // a dataset, a TUM sequence or a robot recording
  const Dataset& ds = input.dataset();
#ifndef TUNNELMAP_HAVE_REPORT
  if (!o.report_path.empty())
    throw ParameterError("--report needs the Qt build of tunnelmap (configure with -DTUNNELMAP_BUILD_GUI=ON)");
#endif
  Progress progress(ds.frames.size());
  DatasetMapping dm = map_dataset(ds, pipeline, !o.no_pose_refinement,
                                  [&](std::size_t done) {
                                    progress.step(done);
                                    return true;
                                  });
  const MappedSequence& mapped = dm.mapped;
  const StationMap& m = mapped.stations;
  const int n = static_cast<int>(dm.maps.size());
  nlohmann::json frames = nlohmann::json::array();
  for (std::size_t k = 0; k < dm.maps.size(); ++k) {
    FrameResult r;  // the per-frame object of detect --json, with the context applied
    r.map = dm.maps[k];
    r.planes.planes.resize(dm.plane_counts[k]);
    r.timings_ms = dm.timings[k];
    nlohmann::json fj = detection_frame_json(k, dm.sources[k], r);
    fj["camera_to_world"] = isometry_to_json(mapped.poses[k]);
    const std::optional<Eigen::Vector3d>& g = ds.frames[k].gravity;  // the IMU's, as the frame carried it
    fj["gravity"] = g ? nlohmann::json{g->x(), g->y(), g->z()} : nlohmann::json(nullptr);
    frames.push_back(fj);
  }

  const nlohmann::json pj = params.to_json();
  if (!o.quiet) print_summary(m, mapped.refinement, dm.notes, dm.detect_ms, dm.map_ms, n);
  if (!dm.notes.gravity.empty()) std::fprintf(stderr, "tunnelmap-cli: note: %s\n", dm.notes.gravity.c_str());
  if (!m.ok && (!o.ply_path.empty() || !o.report_path.empty()))
    throw InputError(o.in.input, "no map to write: " + m.reason);
  if (!o.json_path.empty())
    write_file_atomically(o.json_path, [&](std::ostream& out) {
      nlohmann::json doc = station_map_document(m, pj, frames, o.in.input);
      add_refinement(doc, mapped.refinement);
      doc["notes"] = dm.notes.all();
      out << doc.dump(2) << "\n";
    });
  if (!o.csv_path.empty())
    write_file_atomically(o.csv_path, [&](std::ostream& out) { out << station_map_csv(m); });
  if (!o.diaphragms_csv_path.empty())
    write_file_atomically(o.diaphragms_csv_path, [&](std::ostream& out) { out << diaphragms_csv(m.girder); });
  if (!o.ply_path.empty()) write_sectioned_map_ply(o.ply_path, m.section_maps, pj, plate_outlines(m));
#ifdef TUNNELMAP_HAVE_REPORT
  if (!o.report_path.empty()) write_map_report(o.report_path, o.in.input, m, pj, dm.notes.all(), o.ply_path);
#endif
  ctx.exit_code = 0;
}

}  // namespace

void add_map_command(CLI::App& app, CliContext& ctx) {
  auto o = std::make_shared<MapOptions>();
  auto* cmd = app.add_subcommand(
      "map", "Map the whole tunnel from a posed dataset: stations, sections, deviation from the design");
  add_input_options(cmd, o->in);
  cmd->add_option("--station-step", o->station_step,
                  "Distance between stations along the axis in metres (default 0.10; map.station_step_m)");
  cmd->add_option("--design", o->design,
                  "Design cross-section WIDTHxHEIGHT in metres (tunnel.design_width_m/height_m)");
  cmd->add_option("--tolerance-mm", o->tolerance_mm,
                  "Allowed deviation from the design in mm (default 10; map.tolerance_mm)");
  add_output_option(cmd, "--json", o->json_path, "Write the station map as JSON");
  add_output_option(cmd, "--csv", o->csv_path, "Write one row per station as CSV");
  add_output_option(cmd, "--diaphragms-csv", o->diaphragms_csv_path,
                  "Write one row per diaphragm (station, normal, manhole size, shape, clearances) as CSV");
  add_output_option(cmd, "--ply", o->ply_path, "Write the sectioned map as a binary PLY mesh (world frame)");
  add_output_option(cmd, "--report", o->report_path, "Write the inspection report as PDF");
  cmd->add_flag("--no-pose-refinement", o->no_pose_refinement,
                "Map with the forward-kinematics (or given) poses as they are");
  cmd->add_flag("--quiet,-q", o->quiet, "Print nothing but errors");
  cmd->callback([o, &ctx] { run(*o, ctx); });
}

}  // namespace tunnelmap::cli
