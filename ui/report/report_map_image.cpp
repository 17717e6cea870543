#include "ui/report/report_map_image.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <vector>

#include "core/util/renderer_path.h"
#include "core/util/temp_registry.h"

extern char** environ;

namespace tunnelmap {

namespace {

// Size of the image: the report shows it across the page (about 180 mm, so ~230 dpi).
constexpr const char* kImageSize = "1600x1000";
// Enough of the renderer's stderr to hold its error line.
constexpr std::size_t kMaxErrorBytes = 16384;

std::string last_line(const std::string& text) {
  std::size_t end = text.find_last_not_of(" \r\n\t");
  if (end == std::string::npos) return "";
  const std::size_t start = text.rfind('\n', end);
  return text.substr(start == std::string::npos ? 0 : start + 1, end - (start == std::string::npos ? 0 : start + 1) + 1);
}

// The renderer's error line. A usage error (say, a renderer older than this report, without an
// option it passes) ends with the command-line parser's hint, which says nothing: the line
// before it does, named after the renderer.
std::string error_line(std::string text, const std::string& renderer) {
  static const std::string kHint = "Run with --help for more information.";
  std::string line = last_line(text);
  if (line == kHint) {
    text.erase(text.rfind(kHint));
    line = last_line(text);
    if (!line.empty()) line = renderer + ": " + line;
  }
  return line;
}

// Reads `fd` to its end (keeping the last kMaxErrorBytes) and closes it.
std::string drain(int fd) {
  std::string out;
  char buf[4096];
  for (;;) {
    const ssize_t n = read(fd, buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    out.append(buf, static_cast<std::size_t>(n));
    if (out.size() > kMaxErrorBytes) out.erase(0, out.size() - kMaxErrorBytes);
  }
  close(fd);
  return out;
}

}  // namespace

bool render_map_image_with(const std::string& renderer, const std::string& map_ply, const std::string& png,
                           std::string& why_not) {
  why_not.clear();
  if (access(renderer.c_str(), X_OK) != 0) {
    why_not = "no renderer: " + renderer + " does not exist (it is built with -DTUNNELMAP_BUILD_GUI=ON)";
    return false;
  }
  int err[2];
  if (pipe2(err, O_CLOEXEC) != 0) {
    why_not = std::string("cannot run the renderer: ") + std::strerror(errno);
    return false;
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_adddup2(&actions, err[1], STDERR_FILENO);
  std::vector<std::string> args = {renderer, map_ply, "--screenshot", png, "--view", "oblique", "--cutaway", "--size", kImageSize};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawnattr_t attr;
  posix_spawnattr_init(&attr);
  unblock_interrupts_for_child(&attr);  // the renderer stops on Ctrl-C like any program
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, renderer.c_str(), &actions, &attr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attr);
  close(err[1]);
  if (spawned != 0) {
    close(err[0]);
    why_not = "cannot run " + renderer + ": " + std::strerror(spawned);
    return false;
  }
  const std::string errors = drain(err[0]);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) {
      why_not = std::string("lost the renderer process: ") + std::strerror(errno);
      return false;
    }
  }
  const std::string said = error_line(errors, renderer);
  if (WIFSIGNALED(status)) {
    why_not = "tunnelmap-render was killed by signal " + std::to_string(WTERMSIG(status)) +
              (said.empty() ? "" : " (" + said + ")");
    return false;
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    why_not = said.empty() ? "tunnelmap-render failed with exit status " + std::to_string(WEXITSTATUS(status))
                           : said;
    return false;
  }
  std::error_code ec;
  if (!std::filesystem::exists(png, ec)) {
    why_not = "tunnelmap-render reported success but wrote no " + png;
    return false;
  }
  return true;
}

bool render_map_image(const std::string& map_ply, const std::string& png, std::string& why_not) {
  return render_map_image_with(find_renderer().string(), map_ply, png, why_not);
}

}  // namespace tunnelmap
