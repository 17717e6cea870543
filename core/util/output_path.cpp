#include "core/util/output_path.h"

#include <array>

#include "core/util/error.h"
#include "core/util/sibling_name.h"

namespace tunnelmap {
namespace fs = std::filesystem;

namespace {

// Linux gives up on a path after 40 links (ELOOP); so do we.
constexpr int kMaxLinks = 40;

const char* kind_of(fs::file_type t) {
  switch (t) {
    case fs::file_type::directory: return "a folder";
    case fs::file_type::character: return "a character device";
    case fs::file_type::block: return "a block device";
    case fs::file_type::fifo: return "a FIFO";
    case fs::file_type::socket: return "a socket";
    default: return "not a regular file";
  }
}

// Files that readers take from a dataset folder or a TUM sequence: writing one of them would
// replace the data the run reads.
bool read_from_input_folder(const fs::path& file) {
  static const std::array<const char*, 5> index_files = {"dataset.json", "depth.txt", "rgb.txt",
                                                         "groundtruth.txt", "associations.txt"};
  const std::string name = file.filename().string();
  for (const char* index : index_files)
    if (name == index) return true;
  const std::string ext = file.extension().string();
  return ext == ".png" || ext == ".pcd" || ext == ".oni" || ext == ".jpg";
}

// A path with every link resolved, for comparing paths that need not exist.
fs::path comparable(const std::string& path) {
  std::error_code ec;
  fs::path p = fs::weakly_canonical(output_target(path), ec);
  return ec ? fs::absolute(path).lexically_normal() : p;
}

bool same_file(const fs::path& a, const fs::path& b) {
  std::error_code ec;
  if (a == b) return true;
  return fs::equivalent(a, b, ec) && !ec;  // hard links, bind mounts
}

bool inside(const fs::path& file, const fs::path& folder) {
  const fs::path rel = file.lexically_relative(folder);
  return !rel.empty() && *rel.begin() != "..";
}

}  // namespace

fs::path output_target(const std::string& path) {
  fs::path p(path);
  std::error_code ec;
  for (int hops = 0; fs::is_symlink(fs::symlink_status(p, ec)); ++hops) {
    if (hops == kMaxLinks) throw InputError(path, "cannot write: too many levels of symbolic links");
    const fs::path link = fs::read_symlink(p, ec);
    if (ec) throw InputError(path, "cannot write: " + ec.message());
    p = link.is_absolute() ? link : p.parent_path() / link;
  }
  return p;
}

void check_output_path(const std::string& path) {
  if (path.empty()) throw OutputPathError("''", "empty output path");
  const fs::path target = output_target(path);
  if (target.filename().empty() || target.filename() == "." || target.filename() == "..")
    throw OutputPathError(path, "cannot write: not a file name");
  if (const std::size_t bytes = target.filename().string().size(); bytes > kMaxFileNameBytes)
    throw OutputPathError(path, "cannot write: its name is " + std::to_string(bytes) + " bytes, over the limit of " +
                                    std::to_string(kMaxFileNameBytes) + " for a file name");
  std::error_code ec;
  const fs::file_status st = fs::status(target, ec);
  if (fs::exists(st) && !fs::is_regular_file(st))
    throw OutputPathError(path, std::string("cannot write: it is ") + kind_of(st.type()) +
                               "; only regular files are replaced");
  const fs::path parent = target.parent_path();
  if (!parent.empty() && !fs::is_directory(parent, ec))
    throw InputError(path, "cannot write: folder '" + parent.string() + "' does not exist");
}

void check_outputs_apart(const std::vector<std::string>& inputs, const std::vector<std::string>& outputs) {
  std::vector<fs::path> seen;
  for (const std::string& out : outputs) {
    if (out.empty()) continue;
    const fs::path o = comparable(out);
    for (const std::string& in : inputs) {
      if (in.empty()) continue;
      const fs::path i = comparable(in);
      if (same_file(o, i)) throw OutputPathError(out, "is also an input; refusing to overwrite it");
      std::error_code ec;
      if (fs::is_directory(i, ec) && inside(o, i) && read_from_input_folder(o))
        throw OutputPathError(out, "lies in the input folder " + in + " and may be read by the run; "
                              "refusing to overwrite it");
    }
    for (const fs::path& s : seen)
      if (same_file(o, s)) throw OutputPathError(out, "is given as two outputs; each output needs its own file");
    seen.push_back(o);
  }
}

}  // namespace tunnelmap
