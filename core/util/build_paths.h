#pragma once
// Paths fixed when the project is configured: the source tree and, for tests, the programs and
// folders they run. A source generated per target (cmake/build_paths.cmake) defines the ones
// that target uses. They are not compile definitions, so that no compile command names where the
// checkout lies and a compiler cache serves every clone alike.
namespace tunnelmap::build_paths {
const char* source_dir();           // the checkout (presets, sample and test data)
const char* test_data_dir();        // tests: resources/
const char* cli();                  // tests: the built tunnelmap-cli
const char* gui();                  // tests: the built GUI
const char* render();               // tests: the built tunnelmap-render
const char* sample_dir();           // tests: resources/sample
const char* openni2_runtime_dir();  // tests: OpenNI2 with the simulated-camera driver
const char* ui_test_dir();          // tests: tests/ui (reference images)
const char* test_fixture_dir();     // tests: fixtures made once per build (tests/support/shared_fixture.h)
}  // namespace tunnelmap::build_paths

#define TUNNELMAP_SOURCE_DIR (::tunnelmap::build_paths::source_dir())
#define TUNNELMAP_TEST_DATA_DIR (::tunnelmap::build_paths::test_data_dir())
#define TUNNELMAP_CLI_PATH (::tunnelmap::build_paths::cli())
#define TUNNELMAP_GUI_PATH (::tunnelmap::build_paths::gui())
#define TUNNELMAP_RENDER_PATH (::tunnelmap::build_paths::render())
#define TUNNELMAP_SAMPLE_DIR (::tunnelmap::build_paths::sample_dir())
#define TUNNELMAP_OPENNI2_RUNTIME_DIR (::tunnelmap::build_paths::openni2_runtime_dir())
#define TUNNELMAP_UI_TEST_DIR (::tunnelmap::build_paths::ui_test_dir())
