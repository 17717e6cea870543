// Folder outputs (simulate, convert, evaluate --out, fuse --refined-dataset and
// --mesh-per-compartment) are built beside
// the target and renamed into place; a non-empty folder holding files tunnelmap did not write
// is refused before any work, and no file the user had is ever deleted.
#include "tests/hostile/hostile_checks.h"
#include "tests/support/io_temp_dir.h"

namespace tunnelmap::hostile {
namespace {

namespace fs = std::filesystem;

class FolderOutputs : public ::testing::Test {
 protected:
  fs::path dir() const { return tmp_.path(); }

  // A folder with a file of the user's, and the bytes of that file.
  fs::path users_folder(const std::string& name) const {
    const fs::path folder = dir() / name;
    fs::create_directories(folder);
    write_file(folder / "notes.txt", "my notes");
    return folder;
  }

 private:
  testing::IoTempDir tmp_;
};

TEST_F(FolderOutputs, SimulateRefusesADatasetWithTheUsersFiles) {
  const fs::path ds = dir() / "ds";
  copy_small_dataset(ds);
  write_file(ds / "notes.txt", "my notes");
  const std::string before = read_file(ds / "dataset.json");
  EXPECT_TRUE(exits_with_one_line(run_cli({"simulate", ds.string(), "--frames", "2", "--quiet"}), 2, ds.string()));
  EXPECT_EQ(read_file(ds / "dataset.json"), before);
  EXPECT_EQ(read_file(ds / "notes.txt"), "my notes");
  EXPECT_TRUE(leftovers(dir()).empty());
}

TEST_F(FolderOutputs, SimulateTumRefusesAFolderWithTheUsersFiles) {
  const fs::path folder = users_folder("seq");
  const Outcome o = run_cli({"simulate", folder.string(), "--format", "tum", "--frames", "2", "--quiet"});
  EXPECT_TRUE(exits_with_one_line(o, 2, folder.string()));
  EXPECT_EQ(read_file(folder / "notes.txt"), "my notes");
  EXPECT_TRUE(leftovers(dir()).empty());
}

TEST_F(FolderOutputs, SimulateReplacesItsOwnEarlierOutputWhole) {
  const fs::path ds = dir() / "ds";
  ASSERT_EQ(run_cli({"simulate", ds.string(), "--frames", "3", "--quiet"}).exit_code, 0);
  const Outcome o = run_cli({"simulate", ds.string(), "--frames", "2", "--quiet"});
  ASSERT_EQ(o.exit_code, 0) << o.err;
  EXPECT_FALSE(fs::exists(ds / "depth" / "000002.png"));  // nothing of the old run is left
  EXPECT_TRUE(leftovers(dir()).empty());
}

TEST_F(FolderOutputs, ConvertRefusesAFolderWithTheUsersFiles) {
  const fs::path ds = dir() / "ds", folder = users_folder("tum");
  copy_small_dataset(ds);
  EXPECT_TRUE(exits_with_one_line(run_cli({"convert", ds.string(), folder.string(), "--to", "tum", "-q"}), 2,
                                  folder.string()));
  EXPECT_EQ(read_file(folder / "notes.txt"), "my notes");
}

TEST_F(FolderOutputs, EvaluateOnABadDatasetLeavesNoFolder) {
  const fs::path bad = dir() / "bad", out = dir() / "report";
  fs::create_directories(bad);
  write_file(bad / "dataset.json", "{");
  const Outcome o = run_cli({"evaluate", "--dataset", bad.string(), "--out", out.string(), "-q"});
  EXPECT_TRUE(exits_with_one_line(o, 3, bad.string()));
  EXPECT_FALSE(fs::exists(out));
  EXPECT_TRUE(leftovers(dir()).empty());
}

// fuse's two folder outputs refuse a folder with the user's files before fusing anything.
TEST_F(FolderOutputs, FuseRefusesFoldersWithTheUsersFiles) {
  const fs::path ds = dir() / "ds";
  copy_small_dataset(ds);
  for (const std::string flag : {"--refined-dataset", "--mesh-per-compartment"}) {
    const fs::path folder = users_folder(flag.substr(2));
    const Outcome o = run_cli({"fuse", ds.string(), "--quiet", flag, folder.string()});
    EXPECT_TRUE(exits_with_one_line(o, 2, folder.string())) << flag;
    EXPECT_EQ(read_file(folder / "notes.txt"), "my notes") << flag;
    EXPECT_EQ(std::distance(fs::directory_iterator(folder), fs::directory_iterator()), 1) << flag;
  }
  EXPECT_TRUE(leftovers(dir()).empty());
}

}  // namespace
}  // namespace tunnelmap::hostile
