#include "core/evaluation/girder_protocol.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <sstream>

#include "core/evaluation/joint_sightings.h"
#include "core/io/dataset.h"
#include "core/mapping/dataset_mapping.h"
#include "core/pipeline/pipeline.h"
#include "core/sim/sim_dataset_writer.h"

namespace tunnelmap {

namespace {

// mean, p95 and worst of |v|, and the signed mean (a bias); nulls when empty.
nlohmann::json distribution(std::vector<double> v) {
  if (v.empty()) return {{"n", 0}, {"mean", nullptr}, {"p95", nullptr}, {"worst", nullptr}, {"bias", nullptr}};
  double signed_sum = 0, sum = 0;
  for (double& x : v) signed_sum += x, x = std::abs(x), sum += x;
  std::sort(v.begin(), v.end());
  const std::size_t i95 = static_cast<std::size_t>(std::ceil(0.95 * v.size())) - 1;
  const auto r = [](double x) { return std::round(x * 1000) / 1000; };
  return {{"n", v.size()}, {"mean", r(sum / v.size())}, {"p95", r(v[i95])}, {"worst", r(v.back())},
          {"bias", r(signed_sum / v.size())}};
}

void append(std::vector<double>& to, const std::vector<double>& from) { to.insert(to.end(), from.begin(), from.end()); }

nlohmann::json count_or_null(const std::optional<int>& n) { return n ? nlohmann::json(*n) : nlohmann::json(nullptr); }
nlohmann::json metres_or_null(double m) { return std::isnan(m) ? nlohmann::json(nullptr) : nlohmann::json(std::round(m * 1000) / 1000); }

// Per true joint: its station and the nearest stations either side where frames saw the walls
// that step there (null: none saw them).
nlohmann::json joint_sightings_json(const GirderScore& s) {
  nlohmann::json out = nlohmann::json::array();
  for (std::size_t k = 0; k < s.joint_seen_before_m.size() && k < s.joint_station_m.size(); ++k)
    out.push_back({{"station_m", metres_or_null(s.joint_station_m[k])},
                   {"seen_before_m", metres_or_null(s.joint_seen_before_m[k])},
                   {"seen_after_m", metres_or_null(s.joint_seen_after_m[k])}});
  return out;
}

GirderResult run_one(const GirderDraw& draw, const GirderProtocolOptions& o) {
  namespace fs = std::filesystem;
  const bool keep = !o.keep_dir.empty();
  const fs::path dir = fs::path(keep ? o.keep_dir : o.work_dir) / ("girder-" + std::to_string(draw.index));
  fs::remove_all(dir);
  write_sim_dataset(dir.string(), draw.config);
  const Dataset ds = read_dataset(dir.string());
  Parameters params;
  // Every girder is mapped as a box girder (the field preset): the lab preset's template prior
  // is narrowed around the 0.82 x 1.30 m lab rig and leaves out part of the family's sizes (a
  // girder 1.00 m high sits on its lower bound). The draw's preset is its appearance only.
  params.load_json_file(o.presets_dir + "/field.json");
  params.set_from_strings(o.overrides);
  Pipeline pipeline(params);
  const DatasetMapping dm = map_dataset(ds, pipeline, o.refine_poses);
  GirderResult r;
  r.draw = draw;
  r.frames = static_cast<int>(ds.frames.size());
  r.score = score_girder(dm, ds.ground_truth, ds.raw["frames"]);
  score_joint_sightings(ds, GirderScoringOptions{}, r.score);
  if (!keep) fs::remove_all(dir);
  return r;
}

nlohmann::json girder_json(const GirderResult& r) {
  const GirderScore& s = r.score;
  return {{"index", r.draw.index},
          {"seed", r.draw.config.seed},
          {"summary", r.draw.summary},
          {"constant_section", r.draw.constant_section},
          {"drifted", r.draw.drifted},
          {"frames", r.frames},
          {"width_error_mm", distribution(s.width_error_mm)},
          {"height_error_mm", distribution(s.height_error_mm)},
          {"sections", {{"true", s.sections_true}, {"found", s.sections_found}, {"phantom", s.phantom_sections}}},
          {"joints",
           {{"true", s.joints_true}, {"found", s.joints_found}, {"within_stated_uncertainty", s.joints_within_stated},
            {"seen_within_tolerance", count_or_null(s.joints_seen)},
            {"found_of_seen", count_or_null(s.joints_found_of_seen)},
            {"sightings", joint_sightings_json(s)},
            {"error_mm", distribution(s.joint_error_mm)}}},
          {"plates",
           {{"true", s.plates_true}, {"within_tolerance", s.plates_matched}, {"missed", s.plates_missed},
            {"invented", s.plates_invented}, {"error_mm", distribution(s.plate_error_mm)}}},
          {"manholes",
           {{"width_error_mm", distribution(s.manhole_width_error_mm)},
            {"height_error_mm", distribution(s.manhole_height_error_mm)},
            {"unmeasured", s.manholes_unmeasured}}},
          {"correction_mm", distribution(s.correction_mm)},
          {"correction_deg", distribution(s.correction_deg)},
          {"poses_kept_as_given", s.poses_kept ? nlohmann::json(*s.poses_kept) : nlohmann::json(nullptr)},
          {"pose_error_mm", distribution(s.pose_error_mm)},
          {"pose_error_deg", distribution(s.pose_error_deg)},
          {"pose_error_along_mm", distribution(s.pose_error_along_mm)},
          {"pose_error_across_mm", distribution(s.pose_error_across_mm)},
          {"pose_error_vertical_mm", distribution(s.pose_error_vertical_mm)},
          {"ms_per_frame", std::round(s.ms_per_frame * 100) / 100}};
}

// The family's distributions over the girders with `drifted` poses.
nlohmann::json family(const std::vector<GirderResult>& results, bool drifted) {
  std::vector<double> w, h, joint, plate, mw, mh, corr_mm, corr_deg, pose_mm, pose_deg, along, across, vertical, ms;
  int girders = 0, constant = 0, phantom = 0, joints = 0, joints_found = 0, joints_stated = 0, plates = 0, matched = 0,
      missed = 0, invented = 0, unmeasured = 0, kept = 0, refined = 0;
  std::optional<int> seen, found_of_seen;  // over the girders whose sightings were taken
  for (const GirderResult& r : results) {
    if (r.draw.drifted != drifted) continue;
    const GirderScore& s = r.score;
    ++girders;
    append(w, s.width_error_mm), append(h, s.height_error_mm), append(plate, s.plate_error_mm);
    append(mw, s.manhole_width_error_mm), append(mh, s.manhole_height_error_mm);
    append(corr_mm, s.correction_mm), append(corr_deg, s.correction_deg);
    append(pose_mm, s.pose_error_mm), append(pose_deg, s.pose_error_deg);
    append(along, s.pose_error_along_mm), append(across, s.pose_error_across_mm);
    append(vertical, s.pose_error_vertical_mm);
    ms.push_back(s.ms_per_frame);
    if (s.poses_kept) ++refined, kept += *s.poses_kept ? 1 : 0;
    if (r.draw.constant_section) ++constant, phantom += s.phantom_sections > 0 ? 1 : 0;
    joints += s.joints_true, joints_found += s.joints_found, joints_stated += s.joints_within_stated;
    if (s.joints_seen) seen = seen.value_or(0) + *s.joints_seen, found_of_seen = found_of_seen.value_or(0) + *s.joints_found_of_seen;
    append(joint, s.joint_error_mm);
    plates += s.plates_true, matched += s.plates_matched, missed += s.plates_missed;
    invented += s.plates_invented, unmeasured += s.manholes_unmeasured;
  }
  return {{"girders", girders},
          {"width_error_mm", distribution(w)},
          {"height_error_mm", distribution(h)},
          {"constant_section_girders", constant},
          {"girders_with_phantom_sections", phantom},
          {"joints",
           {{"true", joints}, {"found", joints_found}, {"within_stated_uncertainty", joints_stated},
            {"seen_within_tolerance", count_or_null(seen)}, {"found_of_seen", count_or_null(found_of_seen)},
            {"error_mm", distribution(joint)}}},
          {"plates", {{"true", plates}, {"within_tolerance", matched}, {"missed", missed}, {"invented", invented},
                      {"error_mm", distribution(plate)}}},
          {"manhole_width_error_mm", distribution(mw)},
          {"manhole_height_error_mm", distribution(mh)},
          {"manholes_unmeasured", unmeasured},
          {"correction_mm", distribution(corr_mm)},
          {"correction_deg", distribution(corr_deg)},
          {"poses_kept_as_given", {{"girders", kept}, {"of_refined", refined}}},
          {"pose_error_mm", distribution(pose_mm)},
          {"pose_error_deg", distribution(pose_deg)},
          {"pose_error_along_mm", distribution(along)},
          {"pose_error_across_mm", distribution(across)},
          {"pose_error_vertical_mm", distribution(vertical)},
          {"ms_per_frame", distribution(ms)}};
}

std::string cell(const nlohmann::json& d) {
  if (d["n"].get<int>() == 0) return "–";
  std::ostringstream s;
  s << d["mean"].get<double>() << " / " << d["p95"].get<double>() << " / " << d["worst"].get<double>();
  return s.str();
}

}  // namespace

std::vector<GirderResult> run_girders(const GirderProtocolOptions& o) {
  std::vector<GirderResult> out;
  for (const GirderDraw& d : draw_girders(o.count, o.seed, o.ranges)) {
    // The whole family is drawn either way, so girder N is the same girder with or without `only`.
    if (!o.only.empty() && std::find(o.only.begin(), o.only.end(), d.index) == o.only.end()) continue;
    out.push_back(run_one(d, o));
    if (o.progress) {
      const GirderScore& s = out.back().score;
      std::ostringstream line;
      line << "girder " << d.index << ": " << d.summary << "; " << s.sections_found << " section(s) of "
           << s.sections_true << ", plates " << s.plates_matched << "/" << s.plates_true << " (+"
           << s.plates_invented << " invented)";
      o.progress(line.str());
    }
  }
  return out;
}

nlohmann::json girders_json(const std::vector<GirderResult>& results, const GirderProtocolOptions& o) {
  const GirderRanges& r = o.ranges;
  nlohmann::json girders = nlohmann::json::array();
  for (const GirderResult& g : results) girders.push_back(girder_json(g));
  return {{"protocol", "girders"},
          {"count", o.count},
          {"seed", o.seed},
          {"pose_refinement", o.refine_poses},
          {"ranges",
           {{"length_m", {r.min_length_m, r.max_length_m}},
            {"diaphragm_spacing_m", {r.min_spacing_m, r.max_spacing_m}},
            {"width_m", {r.min_width_m, r.max_width_m}},
            {"height_m", {r.min_height_m, r.max_height_m}},
            {"sectioned_fraction", r.sectioned_fraction},
            {"curved_fraction", r.curved_fraction},
            {"radius_m", {r.min_radius_m, r.max_radius_m}},
            {"max_gradient_pct", r.max_gradient_pct},
            {"max_cross_fall_deg", r.max_cross_fall_deg},
            {"transition_fraction", r.transition_fraction},
            {"transition_m", {r.min_transition_m, r.max_transition_m}},
            {"vertical_curve_fraction", r.vertical_curve_fraction},
            {"vertical_radius_m", {r.min_vertical_radius_m, r.max_vertical_radius_m}},
            {"drifted_fraction", r.drifted_fraction},
            {"drift", {{"translation_mm_per_sqrt_m", r.drift_translation_mm_per_sqrt_m},
                       {"rotation_deg_per_sqrt_m", r.drift_rotation_deg_per_sqrt_m}}},
            {"look_back_fraction", r.look_back_fraction},
            {"stop_spacing_m", {r.min_stop_spacing_m, r.max_stop_spacing_m}}}},
          {"only", o.only.empty() ? nlohmann::json(nullptr) : nlohmann::json(o.only)},
          {"girders", girders},
          {"distributions", {{"exact_poses", family(results, false)}, {"drifted_poses", family(results, true)}}}};
}

std::string girders_markdown(const nlohmann::json& report) {
  std::ostringstream s;
  s << "# Whole-girder evaluation\n\n";
  if (report.value("only", nlohmann::json()).is_array()) s << "Girders " << report["only"].dump() << " of ";
  s << report["count"] << " random girders, seed " << report["seed"]
    << " (`tunnelmap-cli evaluate --protocol girders --count " << report["count"] << " --seed "
    << report["seed"] << "`). Cells: mean / p95 / worst of the absolute error.\n\n"
    << "| measure | exact poses | drifted poses |\n|---|---|---|\n";
  const nlohmann::json& e = report["distributions"]["exact_poses"];
  const nlohmann::json& d = report["distributions"]["drifted_poses"];
  const auto row = [&](const std::string& name, const std::string& a, const std::string& b) {
    s << "| " << name << " | " << a << " | " << b << " |\n";
  };
  row("girders", std::to_string(e["girders"].get<int>()), std::to_string(d["girders"].get<int>()));
  row("station width error (mm)", cell(e["width_error_mm"]), cell(d["width_error_mm"]));
  row("station height error (mm)", cell(e["height_error_mm"]), cell(d["height_error_mm"]));
  const auto phantom = [](const nlohmann::json& f) {
    return std::to_string(f["girders_with_phantom_sections"].get<int>()) + " of " +
           std::to_string(f["constant_section_girders"].get<int>());
  };
  row("constant girders with a phantom section", phantom(e), phantom(d));
  // The true joints that pass `test`, "N of M".
  const auto joints = [](const nlohmann::json& f, const char* test) {
    return std::to_string(f["joints"][test].get<int>()) + " of " + std::to_string(f["joints"]["true"].get<int>());
  };
  row("joints found within 0.2 m", joints(e, "found"), joints(d, "found"));
  row("joints within the uncertainty the map states", joints(e, "within_stated_uncertainty"),
      joints(d, "within_stated_uncertainty"));
  // Joints whose stepping walls frames saw within 0.2 m either side: "found N of M".
  const auto seen = [](const nlohmann::json& f) {
    const nlohmann::json& j = f["joints"];
    if (j["seen_within_tolerance"].is_null()) return std::string("–");
    return std::to_string(j["found_of_seen"].get<int>()) + " of " + std::to_string(j["seen_within_tolerance"].get<int>());
  };
  row("joints found within 0.2 m, of those the frames saw within 0.2 m", seen(e), seen(d));
  row("joint position (mm)", cell(e["joints"]["error_mm"]), cell(d["joints"]["error_mm"]));
  const auto plates = [](const nlohmann::json& f) {
    const nlohmann::json& p = f["plates"];
    return std::to_string(p["within_tolerance"].get<int>()) + " of " + std::to_string(p["true"].get<int>()) +
           " within 20 mm; " + std::to_string(p["missed"].get<int>()) + " missed, " +
           std::to_string(p["invented"].get<int>()) + " invented";
  };
  row("plates", plates(e), plates(d));
  row("plate position error (mm)", cell(e["plates"]["error_mm"]), cell(d["plates"]["error_mm"]));
  row("manhole width error (mm)", cell(e["manhole_width_error_mm"]), cell(d["manhole_width_error_mm"]));
  row("manhole height error (mm)", cell(e["manhole_height_error_mm"]), cell(d["manhole_height_error_mm"]));
  row("manholes not measured", std::to_string(e["manholes_unmeasured"].get<int>()),
      std::to_string(d["manholes_unmeasured"].get<int>()));
  row("pose correction (mm)", cell(e["correction_mm"]), cell(d["correction_mm"]));
  row("pose correction (deg)", cell(e["correction_deg"]), cell(d["correction_deg"]));
  const auto kept = [](const nlohmann::json& f) {
    const nlohmann::json& k = f["poses_kept_as_given"];
    return std::to_string(k["girders"].get<int>()) + " of " + std::to_string(k["of_refined"].get<int>());
  };
  row("girders whose poses the evidence test kept", kept(e), kept(d));
  row("pose error after alignment (mm)", cell(e["pose_error_mm"]), cell(d["pose_error_mm"]));
  row("pose error after alignment (deg)", cell(e["pose_error_deg"]), cell(d["pose_error_deg"]));
  row("pose error along the girder (mm)", cell(e["pose_error_along_mm"]), cell(d["pose_error_along_mm"]));
  row("pose error across the girder (mm)", cell(e["pose_error_across_mm"]), cell(d["pose_error_across_mm"]));
  row("pose error vertically (mm)", cell(e["pose_error_vertical_mm"]), cell(d["pose_error_vertical_mm"]));
  row("detection + map (ms per frame)", cell(e["ms_per_frame"]), cell(d["ms_per_frame"]));
  s << "\n## Girders\n\n| # | girder | stations w / h p95 (mm) | sections | plates | manhole w / h worst (mm) |\n"
       "|---|---|---|---|---|---|\n";
  for (const auto& g : report["girders"]) {
    const auto p95 = [](const nlohmann::json& x) {
      return x["n"].get<int>() ? std::to_string(x["p95"].get<double>()).substr(0, 5) : std::string("–");
    };
    const auto worst = [](const nlohmann::json& x) {
      return x["n"].get<int>() ? std::to_string(x["worst"].get<double>()).substr(0, 5) : std::string("–");
    };
    s << "| " << g["index"] << " | " << g["summary"].get<std::string>() << " | " << p95(g["width_error_mm"])
      << " / " << p95(g["height_error_mm"]) << " | " << g["sections"]["found"] << " of " << g["sections"]["true"]
      << " | " << g["plates"]["within_tolerance"] << "/" << g["plates"]["true"] << " (+" << g["plates"]["invented"]
      << ") | " << worst(g["manholes"]["width_error_mm"]) << " / " << worst(g["manholes"]["height_error_mm"]) << " |\n";
  }
  return s.str();
}

}  // namespace tunnelmap
