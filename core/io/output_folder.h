#pragma once
// Writes a whole output folder (sequence exports) or nothing: files go into a hidden staging
// folder beside the target, which commit() renames into place. If the export fails before that,
// the staging folder is removed, so no partial folder is left and an old one is never destroyed.
#include <filesystem>
#include <functional>
#include <string>

namespace tunnelmap {

class StagedFolder {
 public:
  // `target` may be missing or an empty folder; a non-empty folder only if `replaceable` says
  // so (it is then replaced at commit). InputError naming `target` otherwise.
  explicit StagedFolder(const std::string& target,
                        const std::function<bool(const std::filesystem::path&)>& replaceable = {});
  ~StagedFolder();
  StagedFolder(const StagedFolder&) = delete;
  StagedFolder& operator=(const StagedFolder&) = delete;

  const std::filesystem::path& path() const { return staging_; }  // write here
  const std::filesystem::path& target() const { return target_; }
  void commit();

 private:
  std::filesystem::path target_, staging_;
  std::filesystem::path created_;  // first parent folder we had to create (removed on failure)
  bool replace_ = false, committed_ = false;
};

// The outermost of `dir` and its parents that does not exist yet (empty if `dir` exists): what
// to remove again when a write that creates `dir` fails.
std::filesystem::path first_missing_folder(const std::filesystem::path& dir);

// Creates `dir` (and parents); InputError naming it on failure.
void make_folder(const std::filesystem::path& dir);

// Copies a file byte for byte; InputError naming `to` on failure.
void copy_file_to(const std::string& from, const std::filesystem::path& to);

}  // namespace tunnelmap
