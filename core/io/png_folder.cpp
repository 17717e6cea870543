#include "core/io/png_folder.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "core/io/depth_png.h"
#include "core/util/error.h"

namespace tunnelmap {
namespace fs = std::filesystem;

namespace {

bool is_png_name(const fs::path& p) {
  std::string ext = p.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext == ".png";
}

class PngFolderSource : public FrameSource {
 public:
  PngFolderSource(std::vector<std::string> files, ReadOptions opt)
      : files_(std::move(files)), opt_(std::move(opt)) {}
  std::size_t size() const override { return files_.size(); }
  DepthFrame load(std::size_t i) const override {
    if (i >= files_.size())
      throw InputError(files_.empty() ? std::string() : fs::path(files_[0]).parent_path().string(),
                       "frame index " + std::to_string(i) + " out of range (" +
                           std::to_string(files_.size()) + " frames)");
    return read_depth_png(files_[i], opt_);
  }
  std::string describe(std::size_t i) const override {
    std::string s = "frame " + std::to_string(i) + "/" + std::to_string(files_.size());
    if (i < files_.size()) s += " (" + fs::path(files_[i]).filename().string() + ")";
    return s;
  }

 private:
  std::vector<std::string> files_;
  ReadOptions opt_;
};

}  // namespace

bool natural_less(const std::string& a, const std::string& b) {
  std::size_t i = 0, j = 0;
  while (i < a.size() && j < b.size()) {
    const bool da = std::isdigit(static_cast<unsigned char>(a[i])) != 0;
    const bool db = std::isdigit(static_cast<unsigned char>(b[j])) != 0;
    if (da && db) {
      std::size_t ie = i, je = j;
      while (ie < a.size() && std::isdigit(static_cast<unsigned char>(a[ie]))) ++ie;
      while (je < b.size() && std::isdigit(static_cast<unsigned char>(b[je]))) ++je;
      // Compare by value without overflow: strip leading zeros, then longer is larger.
      std::size_t is = i, js = j;
      while (is + 1 < ie && a[is] == '0') ++is;
      while (js + 1 < je && b[js] == '0') ++js;
      if (ie - is != je - js) return ie - is < je - js;
      const int c = a.compare(is, ie - is, b, js, je - js);
      if (c != 0) return c < 0;
      if (ie - i != je - j) return ie - i < je - j;  // "01" before "1" only to break ties
      i = ie, j = je;
      continue;
    }
    if (a[i] != b[j]) return static_cast<unsigned char>(a[i]) < static_cast<unsigned char>(b[j]);
    ++i, ++j;
  }
  return a.size() - i < b.size() - j;
}

std::vector<std::string> list_depth_pngs(const std::string& folder) {
  std::vector<std::string> names;
  std::error_code ec;
  for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
    std::error_code type_ec;
    if (it->is_regular_file(type_ec) && is_png_name(it->path())) names.push_back(it->path().filename().string());
  }
  if (ec) throw InputError(folder, "cannot list the folder: " + ec.message());
  std::sort(names.begin(), names.end(), natural_less);
  std::vector<std::string> paths;
  paths.reserve(names.size());
  for (const std::string& n : names) paths.push_back((fs::path(folder) / n).string());
  return paths;
}

std::unique_ptr<FrameSource> open_png_folder(const std::string& folder, const ReadOptions& opt) {
  std::vector<std::string> files = list_depth_pngs(folder);
  if (files.empty())
    throw InputError(folder, "folder has no dataset.json, no depth.txt and no depth PNGs (expected a "
                             "dataset folder, a TUM RGB-D sequence or a folder of 16-bit depth PNGs)");
  return std::make_unique<PngFolderSource>(std::move(files), opt);
}

}  // namespace tunnelmap
