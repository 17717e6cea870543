#include "core/util/image_file.h"

#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <vector>

#include "core/util/atomic_file.h"
#include "core/util/error.h"

namespace tunnelmap {

void write_image_file(const std::string& path, const cv::Mat& image) {
  std::vector<uchar> bytes;
  const std::string ext = std::filesystem::path(path).extension().string();
  if (!cv::imencode(ext, image, bytes)) throw InputError(path, "cannot encode the image as " + ext);
  write_file_atomically(path, [&](std::ostream& out) {
    out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  });
}

}  // namespace tunnelmap
