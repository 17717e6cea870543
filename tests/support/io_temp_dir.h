#pragma once
// A fresh temporary folder per test, removed afterwards, plus small file helpers for I/O tests.
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

namespace tunnelmap::testing {

class IoTempDir {
 public:
  IoTempDir() {
    std::random_device rd;
    path_ = std::filesystem::temp_directory_path() /
            ("tunnelmap-io-" + std::to_string(rd()) + std::to_string(rd()));
    std::filesystem::create_directories(path_);
  }
  ~IoTempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  IoTempDir(const IoTempDir&) = delete;
  IoTempDir& operator=(const IoTempDir&) = delete;

  const std::filesystem::path& path() const { return path_; }
  std::string file(const std::string& name) const { return (path_ / name).string(); }

 private:
  std::filesystem::path path_;
};

inline void write_text_file(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

inline std::vector<char> read_binary_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

inline void write_binary_file(const std::string& path, const std::vector<char>& bytes) {
  std::ofstream(path, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

}  // namespace tunnelmap::testing
