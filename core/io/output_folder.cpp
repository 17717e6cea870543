#include "core/io/output_folder.h"

#include <unistd.h>

#include <fstream>
#include <random>
#include <set>

#include "core/util/atomic_file.h"
#include "core/util/error.h"
#include "core/util/sibling_name.h"
#include "core/util/temp_registry.h"

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

// Every regular file and symlink under `dir`, relative to it, the manifest excluded.
std::set<std::string> files_under(const fs::path& dir) {
  std::set<std::string> files;
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(dir, ec); !ec && it != fs::recursive_directory_iterator();
       it.increment(ec)) {
    if (it->is_directory(ec) && !it->is_symlink(ec)) continue;
    const std::string rel = it->path().lexically_relative(dir).generic_string();
    if (rel != kWrittenManifest) files.insert(rel);
  }
  if (ec) throw InputError(dir.string(), "cannot list the folder: " + ec.message());
  return files;
}

void write_manifest(const fs::path& dir) {
  std::string list;
  for (const std::string& f : files_under(dir)) list += f + "\n";
  write_file_atomically((dir / kWrittenManifest).string(), [&](std::ostream& out) { out << list; });
}
}  // namespace

bool written_only_by_us(const fs::path& dir) {
  std::ifstream in(dir / kWrittenManifest);
  if (!in) return false;
  std::set<std::string> listed;
  for (std::string line; std::getline(in, line);) listed.insert(line);
  for (const std::string& f : files_under(dir))
    if (!listed.count(f)) return false;
  return true;
}

StagedFolder::StagedFolder(const std::string& target) {
  if (target.empty()) throw OutputPathError("''", "empty output folder path");
  target_ = fs::absolute(target).lexically_normal();
  if (target_.filename().empty()) target_ = target_.parent_path();  // "out/"
  std::error_code ec;
  if (fs::exists(target_, ec)) {
    if (!fs::is_directory(target_, ec))
      throw OutputPathError(target, "exists and is not a folder; refusing to replace it");
    if (!is_empty_folder(target_)) {
      if (!written_only_by_us(target_))
        throw OutputPathError(target, "folder is not empty and holds files tunnelmap did not write; "
                                      "refusing to write into it (choose a new or empty folder)");
      replace_ = true;
    }
  }
  created_ = first_missing_folder(target_.parent_path());
  staging_ = sibling_name(target_, ".", ".tmp-" + unique_suffix(), false);
  TempRegistry::create(created_.empty() ? staging_ : created_, [&] {
    make_folder(target_.parent_path());
    make_folder(staging_);
  });
}

StagedFolder::~StagedFolder() {
  if (committed_) return;
  const fs::path scratch = created_.empty() ? staging_ : created_;
  std::error_code ec;
  fs::remove_all(scratch, ec);
  TempRegistry::remove(scratch);
}

void StagedFolder::commit() {
  write_manifest(staging_);
  fs::path old;
  std::string failure;
  // The folder moves into place whole or not at all, and never once an interrupt has come.
  TempRegistry::publish(created_.empty() ? staging_ : created_, [&] {
    std::error_code ec;
    if (replace_) {
      old = sibling_name(target_, ".", ".old-" + unique_suffix(), false);
      fs::rename(target_, old, ec);
      if (ec) {
        failure = "cannot replace the folder: " + ec.message();
        old.clear();
        return false;
      }
    } else if (is_empty_folder(target_)) {
      fs::remove(target_, ec);
    }
    fs::rename(staging_, target_, ec);
    if (ec) {
      failure = "cannot move the written folder into place: " + ec.message();
      if (!old.empty()) fs::rename(old, target_, ec);  // put the old folder back
      old.clear();
      return false;
    }
    return true;
  });
  if (!failure.empty()) throw InputError(target_.string(), failure);
  committed_ = true;
  std::error_code ec;
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
