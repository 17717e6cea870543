// The window is split into controllers that each own their docks and actions: no class of the
// GUI (a QObject or QWidget subclass in ui/) spans more than 400 lines, counting its header and
// every source file that defines one of its members.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>

#include "core/util/build_paths.h"

namespace {

namespace fs = std::filesystem;
const fs::path kUi = fs::path(TUNNELMAP_SOURCE_DIR) / "ui";

std::string read_text(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::size_t line_count(const std::string& text) { return std::count(text.begin(), text.end(), '\n'); }

// Class name -> its header, for every Qt class declared in ui/*.h.
std::map<std::string, fs::path> gui_classes() {
  const std::regex decl(R"(class (\w+) : public (Q\w+|QVTKOpenGLNativeWidget))");
  std::map<std::string, fs::path> out;
  for (const auto& e : fs::directory_iterator(kUi)) {
    if (e.path().extension() != ".h") continue;
    const std::string text = read_text(e.path());
    for (std::sregex_iterator m(text.begin(), text.end(), decl), end; m != end; ++m) out[(*m)[1]] = e.path();
  }
  return out;
}

TEST(GuiClasses, NoneSpansMoreThan400Lines) {
  const auto classes = gui_classes();
  ASSERT_GE(classes.size(), 20u);  // the window, its controllers and the widgets
  ASSERT_TRUE(classes.count("MainWindow"));
  ASSERT_TRUE(classes.count("FrameController"));
  std::map<fs::path, std::string> sources;
  for (const auto& e : fs::directory_iterator(kUi))
    if (e.path().extension() == ".cpp") sources[e.path()] = read_text(e.path());
  for (const auto& [name, header] : classes) {
    std::size_t lines = line_count(read_text(header));
    // A definition starts a line ("bool Name::f(", "Name::Name("); a use such as
    // &Name::signal sits inside a function, indented.
    const std::regex defines("(^|\\n)[^\\s/#][^\\n(]*\\b" + name + "::~?\\w+\\(");
    for (const auto& [path, text] : sources)
      if (std::regex_search(text, defines)) lines += line_count(text);
    EXPECT_LE(lines, 400u) << name << " (" << header.filename().string() << " and its sources)";
  }
}

}  // namespace
