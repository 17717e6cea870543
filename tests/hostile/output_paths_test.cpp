// Output paths: only regular files are replaced; a device, a FIFO, a socket or a folder is refused
// before any work (exit 2); a symlink's target is written, atomically; an output that is an
// input, or two outputs on one path, are refused before any work.
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

#include <cstring>

#include "tests/hostile/hostile_checks.h"

namespace tunnelmap::hostile {
namespace {

namespace fs = std::filesystem;

class OutputPaths : public WithSmallDataset {
 protected:
  std::string frame() const { return ds() + "/depth/000000.png"; }
};

TEST_F(OutputPaths, ADeviceBehindASymlinkIsRefused) {
  // Through a link of our own, so that even a writer that replaced the path it was given
  // would replace only the link, never the machine's /dev/null.
  const fs::path link = dir() / "null.json";
  fs::create_symlink("/dev/null", link);
  EXPECT_TRUE(exits_with_one_line(run_cli({"detect", ds(), "-q", "--json", link.string()}), 2, link.string()));
  EXPECT_TRUE(fs::is_symlink(link));
  EXPECT_TRUE(fs::is_character_file("/dev/null"));
}

TEST_F(OutputPaths, AFifoIsRefused) {
  const fs::path fifo = dir() / "out.json";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_TRUE(exits_with_one_line(run_cli({"detect", ds(), "-q", "--json", fifo.string()}), 2, fifo.string()));
  EXPECT_TRUE(fs::is_fifo(fifo));
}

TEST_F(OutputPaths, AFolderIsRefused) {
  const fs::path folder = dir() / "out.csv";
  fs::create_directory(folder);
  write_file(folder / "keep.txt", "mine");
  EXPECT_TRUE(exits_with_one_line(run_cli({"detect", ds(), "-q", "--csv", folder.string()}), 2, folder.string()));
  EXPECT_EQ(read_file(folder / "keep.txt"), "mine");
}

TEST_F(OutputPaths, ASymlinkWritesItsTargetAtomically) {
  fs::create_directory(dir() / "elsewhere");
  const fs::path target = dir() / "elsewhere" / "result.json", link = dir() / "result.json";
  write_file(target, "old");
  fs::create_symlink(target, link);
  const Outcome o = run_cli({"detect", ds(), "-q", "--json", link.string()});
  ASSERT_EQ(o.exit_code, 0) << o.err;
  EXPECT_TRUE(fs::is_symlink(link));
  EXPECT_EQ(fs::read_symlink(link), target);
  EXPECT_EQ(read_file(target).substr(0, 1), "{");
  EXPECT_TRUE(leftovers(dir()).empty());
}

TEST_F(OutputPaths, AnEmptyPathIsRefused) {
  EXPECT_TRUE(exits_with_one_line(run_cli({"detect", ds(), "-q", "--json", ""}), 2, "--json"));
}

TEST_F(OutputPaths, TheDatasetIndexAsOutputIsRefused) {
  const std::string index = ds() + "/dataset.json", before = read_file(index);
  EXPECT_TRUE(exits_with_one_line(run_cli({"map", ds(), "-q", "--json", index}), 2, index));
  EXPECT_EQ(read_file(index), before);
}

TEST_F(OutputPaths, TheInputFrameAsOutputIsRefused) {
  const std::string before = read_file(frame());
  EXPECT_TRUE(exits_with_one_line(run_cli({"detect", frame(), "-q", "--json", frame()}), 2, frame()));
  EXPECT_TRUE(exits_with_one_line(run_cli({"planes", frame(), "--labels", frame()}), 2, frame()));
  EXPECT_EQ(read_file(frame()), before);
}

TEST_F(OutputPaths, TwoOutputsOnOnePathAreRefused) {
  const std::string out = (dir() / "x").string();
  EXPECT_TRUE(exits_with_one_line(run_cli({"detect", ds(), "-q", "--json", out, "--csv", out}), 2, out));
  EXPECT_FALSE(fs::exists(out));
}

TEST_F(OutputPaths, ASocketIsRefused) {
  const fs::path socket_path = dir() / "out.json";
  const int fd = ::socket(AF_UNIX, SOCK_STREAM, 0);
  ASSERT_GE(fd, 0);
  sockaddr_un address{};
  address.sun_family = AF_UNIX;
  ASSERT_LT(socket_path.string().size(), sizeof address.sun_path);
  std::strcpy(address.sun_path, socket_path.c_str());
  ASSERT_EQ(::bind(fd, reinterpret_cast<const sockaddr*>(&address), sizeof address), 0);
  EXPECT_TRUE(exits_with_one_line(run_cli({"detect", ds(), "-q", "--json", socket_path.string()}), 2,
                                  socket_path.string()));
  EXPECT_TRUE(fs::is_socket(socket_path));
  ::close(fd);
}

TEST_F(OutputPaths, ThePresetAsOutputIsRefused) {
  const fs::path preset = dir() / "preset.json";
  write_file(preset, R"({"grow.angle_deg": 5})");
  EXPECT_TRUE(exits_with_one_line(
      run_cli({"detect", ds(), "-q", "--params", preset.string(), "--json", preset.string()}), 2, preset.string()));
  EXPECT_EQ(read_file(preset), R"({"grow.angle_deg": 5})");
}

// A new file inside the input folder that the readers would take from it (an image, a list).
TEST_F(OutputPaths, AnOutputAReaderWouldTakeFromTheInputFolderIsRefused) {
  for (const std::string name : {"labels.png", "depth.txt", "rgb/extra.jpg"}) {
    const std::string out = ds() + "/" + name;
    const std::string flag = name == "labels.png" ? "--labels" : "--json";
    const std::vector<std::string> args = name == "labels.png"
                                              ? std::vector<std::string>{"planes", ds(), "--labels", out}
                                              : std::vector<std::string>{"detect", ds(), "-q", "--json", out};
    EXPECT_TRUE(exits_with_one_line(run_cli(args), 2, out)) << name << " (" << flag << ")";
    EXPECT_FALSE(fs::exists(out)) << name;
  }
}

}  // namespace
}  // namespace tunnelmap::hostile
