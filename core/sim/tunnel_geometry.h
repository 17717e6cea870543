#pragma once
// TunnelGeometry: the simulated rectangular steel tunnel and exact ray casting into it.
// World frame: X along the tunnel axis, Y to the left, Z up. Outer (edge-band) surfaces at
// y = +-W/2, z = 0 and z = H. Each wall: edge band | middle plate (protruding inward by its
// thickness) | edge band; the small faces where a plate steps down to an edge band are
// surfaces too (zone "step"); longitudinal stiffeners are flat bars (zone "stiffener"). Rivets are spherical-cap domes on the edge bands. An optional
// manhole plate (transverse, with an elliptic opening) and an optional end wall close the view.
// With sections, every section has its own walls (and ids), cut at the joints, where the part
// of the transverse plane between the two cross-sections is a surface of its own; diaphragms
// are further plates with the manhole opening.
#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "core/sim/sim_alignment.h"
#include "core/sim/sim_config.h"

namespace tunnelmap {

// One planar surface of the simulated tunnel, listed in dataset.json. Plane (world frame):
// normal_world.dot(x) + offset_world = 0, with the normal pointing into the tunnel / towards
// the cameras.
struct SimSurface {
  int id = 0;
  std::string name;  // e.g. "left/edge_bottom", "section1/top/middle", "joint/0", "diaphragm/2"
  std::string wall;  // "left","right","top","bottom","joint","manhole","diaphragm","end"
  std::string zone;  // "edge","middle","step" or "" (joints and transverse plates)
  int section = -1;  // wall surfaces: their section (0 without sections); -1 otherwise
  int compartment = -1;  // curved girder: the compartment of a wall surface; -1 otherwise
  Eigen::Vector3d normal_world = Eigen::Vector3d::Zero();
  double offset_world = 0.0;

  double distance(const Eigen::Vector3d& x) const { return normal_world.dot(x) + offset_world; }
};

// Ground-truth id of every rivet pixel (rivets are not planar); 0 = nothing hit.
constexpr std::uint16_t kSimRivetId = 65535;

namespace sim {

struct RayHit {
  double t = std::numeric_limits<double>::infinity();  // distance along the unit ray
  int surface_id = 0;        // SimSurface id, kSimRivetId, or 0 for nothing
  int wall = -1;             // SimWall of a wall surface or rivet, -1 otherwise
  int section = -1;          // section of a wall surface or rivet, -1 otherwise
  int compartment = 0;       // curved girder: the compartment hit (0 when straight)
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d local_point = Eigen::Vector3d::Zero();  // (station, y, z); = point if straight
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();  // unit, towards the ray origin side
  double plane_offset = 0.0;                         // planar hits: normal.dot(x) + offset = 0
  bool rivet = false;
  Eigen::Vector3d sphere_center = Eigen::Vector3d::Zero();  // rivet hits
  double sphere_radius = 0.0;

  bool hit() const { return surface_id != 0; }
};

class TunnelGeometry {
 public:
  // `manhole_x` / `end_x`: station of the manhole plate and of the end wall, when present.
  // Throws ParameterError when a curved girder needs more surface ids than 16 bits hold.
  TunnelGeometry(const SimConfig& config, std::optional<double> manhole_x,
                 std::optional<double> end_x);

  // Nearest surface along the ray origin + t * dir (dir must be unit length).
  RayHit cast(const Eigen::Vector3d& origin, const Eigen::Vector3d& dir) const;

  bool on_rust(const RayHit& hit) const;
  // Signed surface relief on rust (metres, along the inward normal; 0 off rust).
  double rust_relief_m(const RayHit& hit) const;
  // Texture value in [-1, 1] (smooth over ~1 cm) for colouring.
  double texture(const RayHit& hit) const;

  const std::vector<SimSurface>& surfaces() const { return surfaces_; }
  const SimAlignment& alignment() const { return alignment_; }
  // Transverse plates with the opening (manhole plate, diaphragms) by station, and their ids.
  struct PlateInfo {
    double station;
    int id;
    double centre_z;  // local height of the opening's centre
    bool manhole_plate = false;  // the one-sided manhole plate (else a diaphragm)
    Eigen::Vector3d centre_world = Eigen::Vector3d::Zero();      // the opening's centre
    Eigen::Vector3d normal_world = Eigen::Vector3d::UnitX();     // unit, to larger stations
    Eigen::Vector3d centreline_world = Eigen::Vector3d::Zero();  // section centre on the plate
  };
  std::vector<PlateInfo> plates() const;
  std::optional<double> start_station() const { return start_x_; }
  std::optional<double> end_station() const { return end_x_; }

 private:
  struct Wall {
    int index;           // SimWall
    Eigen::Vector3d n;   // inward normal
    double d_outer;      // outer plane: n.x + d_outer = 0
    Eigen::Vector3d es;  // across the wall, from one corner to the other
    double s_min, s_max, s_mid_lo, s_mid_hi;  // full wall and middle-plate range along es
    double thickness;
    int edge_lo_id, middle_id, edge_hi_id, step_lo_id, step_hi_id;
    std::vector<double> rivet_row_s, rivet_row_phase;
    struct Bar {  // longitudinal stiffener: s in [s_lo, s_hi], height 0..top above the outer plane
      double s_lo, s_hi, top;
      int top_id, lo_id, hi_id;
    };
    std::vector<Bar> bars;
  };
  struct Section {
    double from_x, to_x;  // [from_x, to_x): the walls' extent along X
    std::vector<Wall> walls;
    bool contains_x(double x) const { return x >= from_x && x < to_x; }
    // (y, z) of p lies in the free cross-section (not behind a wall or inside a plate).
    bool open(const Eigen::Vector3d& p) const;
  };
  struct Plate {
    double x, centre_z;  // opening centred at (y = 0, centre_z)
    int id;
    bool two_sided;      // diaphragms; the manhole plate is seen from the front only
  };
  // A chain joint's transverse surface (curved girder): a plate, the end or start wall.
  struct JointPlate {
    int id = 0;
    bool forward = false, backward = false;  // seen by rays going to larger / smaller stations
    bool full = false;                       // end/start wall: no opening
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();  // opening centre (world)
  };
  struct RustPatch {
    double x, s, rx, rs;  // ellipse centre and semi-axes in wall coordinates
  };
  static constexpr double kMaxRustRx = 0.35;  // largest semi-axis along X (patches sorted by x)

  void build_section(int k, double from_x, double to_x, double W, double H, int& next_id);
  void make_rust();
  void make_chain(const SimConfig& config, int next_id);
  RayHit cast_chain(const Eigen::Vector3d& o, const Eigen::Vector3d& r) const;
  // Walls, steps, rivets and section joints only, at ray parameters in [t_min, best.t).
  void cast_sections(const Eigen::Vector3d& o, const Eigen::Vector3d& r, double t_min,
                     RayHit& best) const;
  void cast_wall(const Section& sec, int k, const Wall& w, const Eigen::Vector3d& o,
                 const Eigen::Vector3d& r, double t_min, RayHit& best) const;
  void cast_rivets(const Section& sec, int k, const Wall& w, const Eigen::Vector3d& o,
                   const Eigen::Vector3d& r, double h0, double dn, double t_min,
                   RayHit& best) const;
  void cast_plates(const Eigen::Vector3d& o, const Eigen::Vector3d& r, RayHit& best) const;
  void cast_bars(const Section& sec, int k, const Wall& w, const Eigen::Vector3d& o,
                 const Eigen::Vector3d& r, double t_min, RayHit& best) const;
  double value_noise(int wall, double x, double s, double cell) const;

  SimConfig config_;
  std::vector<Section> sections_;       // in order along X
  std::vector<int> joint_ids_;          // joint k: between sections k and k + 1
  std::array<Eigen::Vector3d, 4> wall_es_;  // per SimWall, the same in every section
  std::array<double, 4> rust_s_min_{}, rust_s_max_{};  // per SimWall, over all sections
  std::vector<std::vector<RustPatch>> rust_;  // per wall
  std::vector<SimSurface> surfaces_;
  std::optional<double> manhole_x_, end_x_, start_x_;
  std::vector<Plate> plates_;  // manhole plate and diaphragms, by station
  int end_id_ = 0, start_id_ = 0;
  SimAlignment alignment_;
  std::vector<JointPlate> joint_plates_;  // curved girder: per alignment joint
  int local_ids_ = 0;  // curved girder: surface ids per compartment
  std::vector<PlateInfo> plate_info_;
  double sphere_radius_ = 0.0, sphere_depth_ = 0.0;  // rivet sphere; centre behind the plane
  std::uint64_t texture_key_ = 0;
};

}  // namespace sim
}  // namespace tunnelmap
