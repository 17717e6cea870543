#pragma once
// Writes an image file (format from the extension: .png, .jpg) atomically, with every write
// checked. The image is encoded in memory first and written by write_file_atomically: OpenCV's
// file writer neither reports a failed final flush nor keeps libpng's "Write Error" off stderr.
#include <opencv2/core.hpp>
#include <string>

namespace tunnelmap {

// InputError naming `path` when the image cannot be encoded or written.
void write_image_file(const std::string& path, const cv::Mat& image);

}  // namespace tunnelmap
