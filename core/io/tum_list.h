#pragma once
// Parsers for the text lists of a TUM RGB-D sequence: rgb.txt / depth.txt ("timestamp path")
// and groundtruth.txt ("timestamp tx ty tz qx qy qz qw"). Lines starting with '#' and blank
// lines are skipped; timestamps must be finite and strictly increasing.
#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "core/io/input_limits.h"

namespace tunnelmap {

struct TumFileEntry {
  double timestamp_s = 0.0;
  std::string path;  // as written (relative to the sequence folder)
  int line = 0;      // 1-based line in the list
};

struct TumPoseEntry {
  double timestamp_s = 0.0;
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();  // unit, camera-to-world
  int line = 0;
};

// Largest ground-truth coordinate accepted (metres): beyond it a pose is garbage, and blends of
// such values could overflow.
constexpr double kMaxTumTranslation = kMaxPoseTranslationM;

// Largest list file we read (a long sequence's ground truth is a few MB).
constexpr std::size_t kMaxTumListBytes = 256u << 20;

// InputError naming `path` and the line: wrong number of fields, a timestamp that is not a
// finite number or not after the previous one, an empty path.
std::vector<TumFileEntry> parse_tum_file_list(const std::string& text, const std::string& path);

// As above, plus: every value a finite number, |tx|, |ty|, |tz| <= 1e9, the quaternion's norm
// within 1 +- 0.01 (it is then normalised). Quaternion order in the file: qx qy qz qw.
std::vector<TumPoseEntry> parse_tum_groundtruth(const std::string& text, const std::string& path);

// Reads the file (InputError if missing, unreadable or over kMaxTumListBytes), then parses it.
std::vector<TumFileEntry> read_tum_file_list(const std::string& path);
std::vector<TumPoseEntry> read_tum_groundtruth(const std::string& path);

}  // namespace tunnelmap
