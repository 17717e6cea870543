#include "core/evaluation/protocol.h"

#include <algorithm>
#include <cstdio>
#include <map>

#include "core/io/dataset.h"
#include "core/io/frame_source.h"
#include "core/sim/tunnel_simulator.h"
#include "core/util/error.h"

namespace tunnelmap {

namespace {

void check(const ProtocolOptions& o) {
  if (o.frames_per_cell < 1 || o.ransac_frames_per_cell < 0 || o.methods.empty())
    throw ParameterError("evaluation: frames per cell must be >= 1 (R&L frames >= 0) and a method given");
}

std::string cell_line(const CellResult& r) {
  char buf[320];
  std::snprintf(buf, sizeof buf, "%s / %s / %s: %d/%d detected, w %.1f (%.1f) h %.1f (%.1f) mm, %.1f ms/frame",
                r.experiment.c_str(), r.cell.c_str(), method_display_name(r.method), r.detected,
                r.frames, r.width_mean_m * 1000, r.width_std_m * 1000, r.height_mean_m * 1000,
                r.height_std_m * 1000, r.ms_mean);
  return buf;
}

struct CellKey {
  std::string cell;
  Method method;
  bool operator<(const CellKey& o) const {
    return cell != o.cell ? cell < o.cell : static_cast<int>(method) < static_cast<int>(o.method);
  }
};

}  // namespace

Parameters preset_parameters(const ProtocolOptions& options, const std::string& name) {
  Parameters p;
  p.load_json_file(options.presets_dir + "/" + name + ".json");
  p.set_from_strings(options.preset_overrides);
  return p;
}

std::vector<CellResult> run_simulated(SimConfig config, const std::string& experiment,
                                      const std::function<std::string(int group)>& cell_of,
                                      double cell_value, const Parameters& params,
                                      const ProtocolOptions& o) {
  check(o);
  const int groups = std::max<int>(static_cast<int>(config.poses.size()),
                                   config.distance_to_manhole_m ? 1 : static_cast<int>(config.manhole_distances_m.size()));
  config.frames = groups * o.frames_per_cell;
  config.seed = o.seed;
  const TunnelSimulator sim(config);

  std::vector<MethodRunner> runners;
  for (Method m : o.methods) {
    runners.emplace_back(m, params, o.baselines);
    runners.back().set_world_up(Eigen::Vector3d::UnitZ());
  }
  std::map<CellKey, CellAccumulator> acc;
  std::map<CellKey, TunnelContext> contexts;
  std::vector<std::string> order;  // cells in first-seen order
  FrameResult result;
  for (int i = 0; i < sim.frame_count(); ++i) {
    const int g = sim.pose_group(i);
    const int index_in_group = i - (g * sim.frame_count() + groups - 1) / groups;
    const std::string cell = cell_of(g);
    if (std::find(order.begin(), order.end(), cell) == order.end()) order.push_back(cell);
    const SimFrame f = sim.render(i);
    for (const MethodRunner& r : runners) {
      if (r.method() == Method::Ransac && index_in_group >= o.ransac_frames_per_cell) continue;
      const CellKey key{cell, r.method()};
      r.run(f.frame, result, &contexts[key]);
      acc[key].add(result, &f.surface_id);
    }
  }
  std::vector<CellResult> out;
  for (const std::string& cell : order)
    for (Method m : o.methods) {
      const auto it = acc.find({cell, m});
      if (it == acc.end()) continue;
      CellResult r;
      r.experiment = experiment;
      r.cell = cell;
      r.cell_value = cell_value;
      r.method = m;
      r.gt_width_m = config.width_m;
      r.gt_height_m = config.height_m;
      it->second.finish(r);
      if (o.progress) o.progress(cell_line(r));
      out.push_back(r);
    }
  return out;
}

std::vector<CellResult> run_table1(const ProtocolOptions& o) {
  std::vector<CellResult> all;
  const SimConfig lab = SimConfig::from_preset("lab");
  auto part = run_simulated(lab, "lab", [](int g) { return "Pose " + std::to_string(g + 1); }, 0,
                            preset_parameters(o, "lab"), o);
  all.insert(all.end(), part.begin(), part.end());
  const SimConfig field = SimConfig::from_preset("field");
  const std::vector<double> d = field.manhole_distances_m;
  part = run_simulated(field, "field",
                       [d](int g) {
                         char buf[64];
                         std::snprintf(buf, sizeof buf, "%gm to plate", d.at(g % d.size()));
                         return std::string(buf);
                       },
                       0, preset_parameters(o, "field"), o);
  all.insert(all.end(), part.begin(), part.end());
  return all;
}

std::vector<CellResult> run_dataset(const std::string& dir, const Parameters& params,
                                    const ProtocolOptions& o) {
  check(o);
  auto source = open_input(dir, ReadOptions());
  const Dataset* ds = source->dataset();
  if (!ds) throw InputError(dir, "not a dataset folder (no dataset.json)");
  if (!ds->gt_width_m || !ds->gt_height_m)
    throw InputError(ds->json_path, "no ground truth width and height: cannot evaluate");
  std::vector<CellResult> out;
  for (Method m : o.methods) {
    MethodRunner runner(m, params, o.baselines);
    runner.set_world_up(ds->up);
    TunnelContext context;
    CellAccumulator acc;
    FrameResult result;
    const std::size_t n = m == Method::Ransac
                              ? std::min<std::size_t>(source->size(), o.ransac_frames_per_cell)
                              : source->size();
    for (std::size_t i = 0; i < n; ++i) {
      const DepthFrame frame = source->load(i);
      const std::vector<std::uint16_t> truth = ds->load_gt_surfaces(i);
      runner.run(frame, result, &context);
      acc.add(result, truth.empty() ? nullptr : &truth);
    }
    CellResult r;
    r.experiment = dir;
    r.cell = "all frames";
    r.method = m;
    r.gt_width_m = ds->gt_width_m;
    r.gt_height_m = ds->gt_height_m;
    acc.finish(r);
    if (o.progress) o.progress(cell_line(r));
    out.push_back(r);
  }
  return out;
}

}  // namespace tunnelmap
