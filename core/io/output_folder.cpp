#include "core/io/output_folder.h"

#include <unistd.h>

#include <random>

#include "core/util/error.h"

namespace tunnelmap {

namespace fs = std::filesystem;

namespace {
std::string unique_suffix() {
  std::random_device rd;
  return std::to_string(::getpid()) + "-" + std::to_string(rd() % 1000000);
}

bool is_empty_folder(const fs::path& p) {
  std::error_code ec;
  return fs::is_directory(p, ec) && fs::is_empty(p, ec) && !ec;
}
}  // namespace

StagedFolder::StagedFolder(const std::string& target,
                           const std::function<bool(const fs::path&)>& replaceable) {
  if (target.empty()) throw InputError("", "no output folder given");
  target_ = fs::absolute(target).lexically_normal();
  if (target_.filename().empty()) target_ = target_.parent_path();  // "out/"
  std::error_code ec;
  if (fs::exists(target_, ec)) {
    if (!fs::is_directory(target_, ec)) throw InputError(target, "exists and is not a folder");
    if (!is_empty_folder(target_)) {
      if (!replaceable || !replaceable(target_))
        throw InputError(target, "folder is not empty; refusing to write into it (choose a new or "
                                 "empty folder)");
      replace_ = true;
    }
  }
  created_ = first_missing_folder(target_.parent_path());
  make_folder(target_.parent_path());
  staging_ = target_.parent_path() / ("." + target_.filename().string() + ".tmp-" + unique_suffix());
  make_folder(staging_);
}

StagedFolder::~StagedFolder() {
  if (committed_) return;
  std::error_code ec;
  fs::remove_all(created_.empty() ? staging_ : created_, ec);
}

void StagedFolder::commit() {
  std::error_code ec;
  fs::path old;
  if (replace_) {
    old = target_.parent_path() / ("." + target_.filename().string() + ".old-" + unique_suffix());
    fs::rename(target_, old, ec);
    if (ec) throw InputError(target_.string(), "cannot replace the folder: " + ec.message());
  } else if (is_empty_folder(target_)) {
    fs::remove(target_, ec);
  }
  fs::rename(staging_, target_, ec);
  if (ec) {
    const std::string why = ec.message();
    if (!old.empty()) fs::rename(old, target_, ec);  // put the old folder back
    throw InputError(target_.string(), "cannot move the written folder into place: " + why);
  }
  committed_ = true;
  if (!old.empty()) fs::remove_all(old, ec);
}

fs::path first_missing_folder(const fs::path& dir) {
  std::error_code ec;
  fs::path missing;
  for (fs::path p = dir; !p.empty() && !fs::exists(p, ec); p = p.parent_path()) {
    missing = p;
    if (p == p.parent_path()) break;
  }
  return missing;
}

void make_folder(const fs::path& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir, ec))
    throw InputError(dir.string(), "cannot create folder" + (ec ? ": " + ec.message() : std::string()));
}

void copy_file_to(const std::string& from, const fs::path& to) {
  std::error_code ec;
  fs::copy_file(from, to, fs::copy_options::overwrite_existing, ec);
  if (ec) throw InputError(to.string(), "cannot copy " + from + ": " + ec.message());
}

}  // namespace tunnelmap
