#pragma once
// Writes a whole output folder (sequence exports, simulated datasets, evaluation reports) or
// nothing: files go into a hidden staging folder beside the target, which commit() renames
// into place. If the run fails or is interrupted before that, the staging folder is removed,
// so no partial folder is left and an old one is never destroyed.
//
// A non-empty target is replaced only when an earlier commit wrote it: commit() lists every
// file it wrote in the folder's manifest (kWrittenManifest), and a folder holding any file
// not on that list (the user's own notes, or a dataset from elsewhere) is refused, so that a
// file we did not write is never deleted.
#include <filesystem>
#include <string>

namespace tunnelmap {

inline constexpr const char* kWrittenManifest = ".tunnelmap-written";

class StagedFolder {
 public:
  // `target` may be missing, an empty folder or a folder an earlier commit wrote (replaced at
  // commit); InputError naming `target` otherwise.
  explicit StagedFolder(const std::string& target);
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

// True when every file under `dir` is listed in its manifest: a folder only we wrote.
bool written_only_by_us(const std::filesystem::path& dir);

// The outermost of `dir` and its parents that does not exist yet (empty if `dir` exists): what
// to remove again when a write that creates `dir` fails.
std::filesystem::path first_missing_folder(const std::filesystem::path& dir);

// Creates `dir` (and parents); InputError naming it on failure.
void make_folder(const std::filesystem::path& dir);

// Copies a file byte for byte; InputError naming `to` on failure.
void copy_file_to(const std::string& from, const std::filesystem::path& to);

}  // namespace tunnelmap
