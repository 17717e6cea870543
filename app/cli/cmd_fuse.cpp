// `tunnelmap-cli fuse DATASET [--mesh OUT.ply] [--map OUT.ply] [--json FILE]
// [--mesh-per-compartment DIR [--piece-length M]] [--dense]`: fuses every posed frame (explicit
// pose, else forward kinematics of the arm's joints) into a sparse TSDF volume, extracts a
// coloured mesh (whole, or in pieces along the tunnel) and merges the per-frame tunnel maps
// along the tunnel axis.
#include <filesystem>
#include <iostream>
#include <memory>

#include "app/cli/commands.h"
#include "app/cli/input_options.h"
#include "app/cli/output_options.h"
#include "core/export/map_ply.h"
#include "core/export/mesh_ply.h"
#include "core/fusion/fuse_dataset.h"
#include "core/fusion/fusion_options.h"
#include "core/fusion/mesh_accuracy.h"
#include "core/fusion/mesh_pieces_writer.h"
#include "core/io/dataset.h"
#include "core/io/refined_dataset.h"
#include "core/kinematics/robot_json.h"
#include "core/mapping/mapping_notes.h"
#include "core/report/pose_refinement_json.h"
#include "core/report/station_map_json.h"
#include "core/util/atomic_file.h"
#include "core/util/error.h"
#include "mesh/sparse_mesher.h"
#include "mesh/tsdf_mesher.h"

namespace tunnelmap::cli {

namespace {

struct FuseOptions {
  InputOptions in;
  std::string mesh_path, map_path, json_path, refined_dataset, pieces_dir;
  double piece_length_m = 0.0;  // 0: cut at the dataset's diaphragms
  bool dense = false;
  bool prefer_joints = false;
  bool no_pose_refinement = false;
  bool quiet = false;
};

nlohmann::json vec(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

const PoseCorrection* correction_of(const PoseRefinement& r, int group) {
  if (!r.ran) return nullptr;
  for (const PoseCorrection& c : r.groups)
    if (c.group == group) return &c;
  return nullptr;
}

std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (const std::string& x : v) s += (s.empty() ? "" : ", ") + x;
  return s;
}

// {"rotation_deg", "translation_mm", "constrained", "degenerate", "samples"}; null when the
// poses were not refined.
nlohmann::json refinement_json(const PoseCorrection* c) {
  if (!c) return nullptr;
  return {{"rotation_deg", c->rotation_deg},
          {"translation_mm", c->translation_mm},
          {"constrained", c->constrained},
          {"degenerate", c->degenerate},
          {"samples", c->samples},
          {"correction", isometry_to_json(c->delta)}};
}

// A folder that a command will fill: new or empty.
void check_new_folder(const std::string& dir) {
  std::error_code ec;
  if (std::filesystem::exists(dir, ec) &&
      !(std::filesystem::is_directory(dir, ec) && std::filesystem::is_empty(dir, ec)))
    throw OutputPathError(dir, "the output folder must be new or empty");
  const std::filesystem::path parent = std::filesystem::absolute(dir).parent_path();
  if (!std::filesystem::is_directory(parent, ec))
    throw InputError(dir, "its parent folder does not exist");
}

// The dataset's diaphragm stations along world x (simulated girders carry them).
std::vector<double> known_diaphragms(const Dataset& ds) {
  std::vector<double> x;
  if (ds.ground_truth.is_object() && ds.ground_truth.contains("diaphragms_x_m") &&
      ds.ground_truth["diaphragms_x_m"].is_array())
    for (const auto& v : ds.ground_truth["diaphragms_x_m"])
      if (v.is_number()) x.push_back(v.get<double>());
  return x;
}

// The pieces of --mesh-per-compartment: at the diaphragms along world x, or every
// --piece-length metres along the merged map's axis (else the mesh's principal axis).
void write_pieces(const FuseOptions& o, const Dataset& ds, const FusionResult& r, const TriangleMesh& mesh,
                  const nlohmann::json& header) {
  PieceIndexInfo info;
  info.header = header;
  if (o.piece_length_m > 0) {
    if (r.merged.map.detected)
      info.axis = {r.merged.map.axis_point, r.merged.map.axis_dir.normalized()};
    else
      info.axis = principal_axis(mesh);
    info.cut_by = "length";
    info.piece_length_m = o.piece_length_m;
    info.cuts_m = regular_cuts(mesh, info.axis, o.piece_length_m);
  } else {
    info.axis = StationAxis();  // the simulator's girder runs along world x
    info.cut_by = "diaphragms";
    info.cuts_m = known_diaphragms(ds);
  }
  write_mesh_pieces(o.pieces_dir, split_mesh(mesh, info.axis, info.cuts_m), info, header["params"]);
}

// {"kind", "blocks", "voxels", "bytes", "voxel_m"}, and the dense box's origin and dims.
nlohmann::json volume_json(const FusionResult& r) {
  if (r.volume)
    return {{"kind", "sparse"},
            {"blocks", r.volume->block_count()},
            {"voxels", r.volume->voxel_count()},
            {"bytes", r.volume->memory_bytes()},
            {"voxel_m", r.volume->voxel_m()},
            {"grid_yaw_deg", r.lattice.yaw_deg},
            {"grid_heading", heading_source_name(r.lattice.source)},
            {"grid_offset_m", vec(r.lattice.offset_m)},
            {"grid_offset_fit_ms", r.lattice.offset_fit_ms}};
  const VoxelGrid& g = r.dense_volume->grid();
  return {{"kind", "dense"},
          {"blocks", nullptr},
          {"voxels", g.count()},
          {"bytes", r.dense_volume->memory_bytes()},
          {"voxel_m", g.voxel_m},
          {"origin", vec(g.origin)},
          {"dims", {g.dims.x(), g.dims.y(), g.dims.z()}}};
}

std::string volume_summary(const FusionResult& r) {
  char text[160];
  if (r.volume)
    std::snprintf(text, sizeof text, "%zu blocks (%zu voxels of %g mm, %zu MiB)", r.volume->block_count(),
                  r.volume->voxel_count(), r.volume->voxel_m() * 1000.0, r.volume->memory_bytes() >> 20);
  else {
    const VoxelGrid& g = r.dense_volume->grid();
    std::snprintf(text, sizeof text, "%dx%dx%d voxels of %g mm (dense, %zu MiB)", g.dims.x(), g.dims.y(),
                  g.dims.z(), g.voxel_m * 1000.0, r.dense_volume->memory_bytes() >> 20);
  }
  return text;
}

// Data beyond the fusion limits is a problem of the input: exit 3, naming it.
FusionResult fuse_with_limits(const Dataset& ds, const Parameters& params, const FuseSettings& s,
                              const std::string& input) {
  try {
    return fuse_dataset(ds, params, s);
  } catch (const FusionDataError& e) {
    throw InputError(input, e.what());
  }
}

void run(const FuseOptions& o, CliContext& ctx) {
  const Parameters params = o.in.parameters();
  check_outputs({o.in.input, o.in.params_file}, {o.mesh_path, o.map_path, o.json_path});  // fail now
  const DatasetInput input(o.in);  // a dataset, a TUM sequence or a robot recording
  const Dataset& ds = input.dataset();
  if (!o.refined_dataset.empty()) check_new_folder(o.refined_dataset);
  if (!o.pieces_dir.empty()) {
    check_new_folder(o.pieces_dir);
    if (!(o.piece_length_m > 0) && known_diaphragms(ds).empty())
      throw ParameterError("fuse: " + o.in.input + " knows no diaphragms: give --piece-length M with "
                           "--mesh-per-compartment");
  }

  FuseSettings s;
  s.prefer_joints = o.prefer_joints;
  s.refine_poses = !o.no_pose_refinement;
  s.dense = o.dense;
  Progress progress(ds.frames.size() * 2);
  s.progress = [&](const std::string& stage, int done, int) {
    progress.step(static_cast<std::size_t>(done) + (stage == "integrate" ? ds.frames.size() : 0));
  };
  FusionResult r = fuse_with_limits(ds, params, s, o.in.input);
  const nlohmann::json volume_doc = volume_json(r);
  const std::string volume_text = volume_summary(r);
  MeshStats ms;
  const int min_weight = fusion_options(params).min_weight;
  // The volume is not needed past the mesh: its blocks are freed as the mesher sweeps past
  // them (a 100 m girder's blocks and mesh are ~600 MB and ~300 MB), and the rest before the
  // mesh is copied for the accuracy and cut into pieces.
  const TriangleMesh mesh = r.volume ? extract_mesh_releasing(*r.volume, min_weight, &ms)
                                     : extract_mesh(*r.dense_volume, min_weight, &ms);
  r.timings_ms["mesh"] = ms.milliseconds;
  r.volume.reset();
  r.dense_volume.reset();

  const nlohmann::json pj = params.to_json();
  if (!o.mesh_path.empty()) write_mesh_ply(o.mesh_path, mesh, pj);
  if (!o.map_path.empty()) {
    if (!r.merged.map.detected)
      throw InputError(o.in.input, "no frame found the tunnel, so there is no map to write (" +
                                       r.merged.map.reason + ")");
    // The map follows the sections (the same map as `map --ply`), in the world frame.
    if (!r.stations.section_maps.empty())
      write_sectioned_map_ply(o.map_path, r.stations.section_maps, pj, plate_outlines(r.stations));
    else
      write_map_ply(o.map_path, r.merged.map, pj);
  }

  // Simulated datasets carry their true surfaces: report the mesh's accuracy against them.
  const std::vector<PlaneRef> truth = ground_truth_planes(ds.ground_truth);
  const MeshAccuracy acc = mesh_accuracy(mesh, truth, 0.010);
  // Up to where the whole sequence sits in the world: the map's own consistency.
  const Eigen::Isometry3d to_truth = align_mesh_to_planes(mesh, truth);
  const MeshAccuracy aligned = mesh_accuracy(mesh, truth, 0.010, to_truth);
  if (!o.refined_dataset.empty()) {
    std::vector<Eigen::Isometry3d> refined;
    for (const FusedFrame& f : r.frames) refined.push_back(f.camera_to_world);
    write_dataset_with_poses(ds, refined, o.refined_dataset);
  }
  const nlohmann::json header = {
      {"tool", std::string("tunnelmap ") + TUNNELMAP_VERSION}, {"input", o.in.input}, {"params", pj}};
  if (!o.pieces_dir.empty()) write_pieces(o, ds, r, mesh, header);
  const TunnelMap& m = r.merged.map;
  if (!o.quiet) {
    std::cout << "fused " << r.frames.size() << " frames into " << volume_text << ": "
              << mesh.vertices.size() << " vertices, " << mesh.triangles.size() << " triangles\n";
    if (m.detected)
      std::printf("map: %.3f x %.3f m over %.2f m of tunnel, %d frames merged\n", m.width_m,
                  m.height_m, m.extent_max_m - m.extent_min_m, r.merged.frames_merged);
    else
      std::cout << "map: " << m.status << " (" << m.reason << ")\n";
    for (std::size_t i = 0; i < r.stations.sections.size(); ++i) {
      const Section& sec = r.stations.sections[i];
      std::printf("section %zu: %.2f to %.2f m, width %.4f m, height %.4f m\n", i + 1, sec.from_m,
                  sec.to_m, sec.width_m, sec.height_m);
    }
    for (const PoseGroupStatus& p : r.merged.poses) {
      std::cout << "pose " << p.group << " (frames " << p.frames.front() << "-" << p.frames.back()
                << "): " << p.message;
      if (const PoseCorrection* c = correction_of(r.refinement, p.group))
        std::printf("; refined by %.2f deg, %.1f mm%s%s", c->rotation_deg, c->translation_mm,
                    c->degenerate.empty() ? "" : "; not constrained: ",
                    join(c->degenerate).c_str());
      std::cout << "\n";
    }
    for (const std::string& line : unchecked_pose_notes(r.refinement, r.stations.girder.unchecked_plates))
      std::cout << line << "\n";
    for (const std::string& line : plates_beyond_range_notes(r.stations.girder.plates_beyond_range))
      std::cout << line << "\n";
    if (!truth.empty()) {
      std::printf("mesh vs ground truth: %.2f %% of vertices within 10 mm (median %.1f mm, "
                  "p95 %.1f mm)\n", 100.0 * acc.fraction_within, acc.median_m * 1000.0,
                  acc.p95_m * 1000.0);
      std::printf("mesh vs ground truth after one rigid alignment: %.2f %% within 10 mm (median "
                  "%.1f mm, p95 %.1f mm)\n", 100.0 * aligned.fraction_within,
                  aligned.median_m * 1000.0, aligned.p95_m * 1000.0);
    }
    std::printf("time: load+detect %.0f ms, map and pose refinement %.0f ms (refinement %.0f ms), "
                "integrate %.0f ms, mesh %.0f ms\n", r.timings_ms["load+detect"],
                r.timings_ms["map"], r.refinement.ms, r.timings_ms["integrate"], r.timings_ms["mesh"]);
  }
  if (!o.json_path.empty()) {
    nlohmann::json frames = nlohmann::json::array();
    for (const FusedFrame& f : r.frames)
      frames.push_back({{"index", f.index},
                        {"pose_source", pose_source_name(f.pose_source)},
                        {"pose_group", f.pose_group},
                        {"camera_to_world", isometry_to_json(f.camera_to_world)},
                        {"given_camera_to_world", isometry_to_json(f.given_camera_to_world)},
                        {"status", f.map.status},
                        {"width_m", f.map.width_m},
                        {"height_m", f.map.height_m}});
    nlohmann::json poses = nlohmann::json::array();
    for (const PoseGroupStatus& p : r.merged.poses)
      poses.push_back({{"group", p.group},
                       {"frames", p.frames},
                       {"detected_frames", p.detected_frames},
                       {"rescan", p.rescan},
                       {"status", p.status},
                       {"message", p.message},
                       {"camera_to_world", isometry_to_json(p.camera_to_world)},
                       {"refinement", refinement_json(correction_of(r.refinement, p.group))}});
    nlohmann::json sections = nlohmann::json::array();  // as in `map --json`
    for (const Section& sec : r.stations.sections)
      sections.push_back(section_json(sec, r.stations.options, sections.empty()));
    nlohmann::json doc = header;
    doc.update({
        {"volume", volume_doc},
        {"mesh",
         {{"vertices", mesh.vertices.size()},
          {"triangles", mesh.triangles.size()},
          {"dropped_unseen_triangles", ms.dropped_unseen}}},
        {"map",
         {{"detected", m.detected},
          {"status", m.status},
          {"reason", m.reason},
          {"width_m", m.width_m},
          {"height_m", m.height_m},
          {"axis_point", vec(m.axis_point)},
          {"axis_dir", vec(m.axis_dir)},
          {"up", vec(m.up)},
          {"extent_m", {m.extent_min_m, m.extent_max_m}},
          {"frames_merged", r.merged.frames_merged},
          {"width_spread_m", r.merged.width_spread_m},
          {"height_spread_m", r.merged.height_spread_m}}},
        {"poses", poses},
        {"sections", sections},
        {"pose_refinement", pose_refinement_json(r.refinement)},
        {"ground_truth_accuracy",
         truth.empty() ? nlohmann::json(nullptr)
                       : nlohmann::json{{"fraction_within_10mm", acc.fraction_within},
                                        {"median_m", acc.median_m},
                                        {"p95_m", acc.p95_m},
                                        {"rms_m", acc.rms_m},
                                        {"aligned_fraction_within_10mm", aligned.fraction_within},
                                        {"aligned_median_m", aligned.median_m},
                                        {"aligned_p95_m", aligned.p95_m},
                                        {"alignment", isometry_to_json(to_truth)}}},
        {"frames", frames},
        {"timings_ms", r.timings_ms}});
    write_file_atomically(o.json_path, [&](std::ostream& out) { out << doc.dump(2) << "\n"; });
  }
  ctx.exit_code = 0;
}

}  // namespace

void add_fuse_command(CLI::App& app, CliContext& ctx) {
  auto opt = std::make_shared<FuseOptions>();
  CLI::App* cmd = app.add_subcommand(
      "fuse", "Fuse a posed dataset (poses or arm joints) into a coloured mesh and one tunnel map");
  add_input_options(cmd, opt->in);
  add_output_option(cmd, "--mesh", opt->mesh_path, "Fused mesh as binary PLY (colours, normals)");
  add_output_option(cmd, "--map", opt->map_path, "Merged tunnel map as PLY (world frame)");
  add_output_option(cmd, "--json", opt->json_path, "Summary: volume, mesh, merged map, per-pose verdicts");
  cmd->add_flag("--use-joints", opt->prefer_joints,
                "Pose from the arm's forward kinematics even where a frame has a \"pose\"");
  cmd->add_flag("--no-pose-refinement", opt->no_pose_refinement,
                "Fuse with the forward-kinematics (or given) poses as they are: no correction "
                "against the tunnel map");
  cmd->add_option("--refined-dataset", opt->refined_dataset,
                  "Write the dataset with the refined poses to this new folder (other commands "
                  "read it like any dataset)");
  cmd->add_option("--mesh-per-compartment", opt->pieces_dir,
                  "Write the mesh in pieces to this new folder: one binary PLY per compartment "
                  "(between the dataset's diaphragms) and pieces.json with their extents");
  cmd->add_option("--piece-length", opt->piece_length_m,
                  "With --mesh-per-compartment: pieces of this many metres along the tunnel "
                  "instead (needed when no diaphragms are known)")
      ->check(CLI::PositiveNumber);
  cmd->add_flag("--dense", opt->dense,
                "Fuse into the dense volume over the data's bounding box (for comparison; memory "
                "grows with the box)");
  cmd->add_flag("--quiet", opt->quiet, "Print nothing on success");
  cmd->callback([opt, &ctx] { run(*opt, ctx); });
}

}  // namespace tunnelmap::cli
