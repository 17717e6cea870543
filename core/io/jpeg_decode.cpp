#include "core/io/jpeg_decode.h"

#include <csetjmp>
#include <cstdio>
#include <cstdlib>
#include <cstring>

// jpeglib.h needs size_t and FILE declared first.
#include <jpeglib.h>

#include "core/util/error.h"

namespace tunnelmap {
namespace {

enum class Failure { None, Library, Components, TooLarge, OutOfMemory };

// What libjpeg said, and the decoded image. Plain data: libjpeg leaves by longjmp, which must
// not skip a C++ destructor, so nothing with one lives in the frames it unwinds.
struct JpegSession {
  jpeg_error_mgr errors;  // first: libjpeg hands the handlers a pointer to it
  std::jmp_buf jump;
  char message[JMSG_LENGTH_MAX];
  Failure failure;
  long long max_pixels;
  unsigned width, height;
  int components;
  unsigned char* pixels;  // malloc'd width x height x 3
};

[[noreturn]] void fail(j_common_ptr jpeg) {
  auto* s = reinterpret_cast<JpegSession*>(jpeg->err);
  (*jpeg->err->format_message)(jpeg, s->message);
  s->failure = Failure::Library;
  std::longjmp(s->jump, 1);
}

// Warnings (level -1: "Corrupt JPEG data", "Premature end of JPEG file") end the decode with
// their message; trace messages (level >= 0) are dropped. Nothing reaches stderr.
void on_message(j_common_ptr jpeg, int level) {
  if (level < 0) fail(jpeg);
}

void on_output(j_common_ptr) {}

// Decodes into session.pixels; false with session.failure set on any problem. The libjpeg
// object lives in the caller's frame (plain data), destroyed on both paths.
bool run_libjpeg(JpegSession& s, jpeg_decompress_struct& jpeg, const unsigned char* data, unsigned long size) {
  if (setjmp(s.jump)) return false;
  jpeg_create_decompress(&jpeg);
  jpeg_mem_src(&jpeg, data, size);
  jpeg_read_header(&jpeg, TRUE);
  s.width = jpeg.image_width;
  s.height = jpeg.image_height;
  s.components = jpeg.num_components;
  if (jpeg.num_components != 3 || (jpeg.jpeg_color_space != JCS_YCbCr && jpeg.jpeg_color_space != JCS_RGB)) {
    s.failure = Failure::Components;
    return false;
  }
  if (static_cast<long long>(s.width) * s.height > s.max_pixels) {
    s.failure = Failure::TooLarge;
    return false;
  }
  jpeg.out_color_space = JCS_RGB;
  jpeg_start_decompress(&jpeg);
  const std::size_t row_bytes = static_cast<std::size_t>(jpeg.output_width) * 3;
  if (jpeg.output_components != 3 || jpeg.output_width != s.width || jpeg.output_height != s.height) {
    s.failure = Failure::Components;
    return false;
  }
  s.pixels = static_cast<unsigned char*>(std::malloc(row_bytes * s.height));
  if (!s.pixels) {
    s.failure = Failure::OutOfMemory;
    return false;
  }
  while (jpeg.output_scanline < jpeg.output_height) {
    JSAMPROW row = s.pixels + jpeg.output_scanline * row_bytes;
    jpeg_read_scanlines(&jpeg, &row, 1);
  }
  jpeg_finish_decompress(&jpeg);
  return true;
}

}  // namespace

std::vector<std::uint8_t> decode_jpeg_rgb8(const std::vector<std::uint8_t>& bytes, const std::string& path,
                                           long long max_pixels, int& width, int& height) {
  JpegSession s{};
  s.max_pixels = max_pixels;
  jpeg_decompress_struct jpeg{};
  jpeg.err = jpeg_std_error(&s.errors);
  s.errors.error_exit = fail;
  s.errors.emit_message = on_message;
  s.errors.output_message = on_output;
  const bool ok = run_libjpeg(s, jpeg, bytes.data(), static_cast<unsigned long>(bytes.size()));
  jpeg_destroy_decompress(&jpeg);
  if (!ok) {
    std::free(s.pixels);
    switch (s.failure) {
      case Failure::Components:
        throw InputError(path, "RGB images must be 8-bit 3-channel colour (a " + std::to_string(s.components) +
                                   "-component JPEG)");
      case Failure::TooLarge:
        throw InputError(path, "image of " + std::to_string(s.width) + "x" + std::to_string(s.height) +
                                   " pixels is too large (input.max_image_pixels is " + std::to_string(max_pixels) + ")");
      case Failure::OutOfMemory: throw InputError(path, "out of memory decoding the JPEG");
      default: throw InputError(path, std::string("corrupt JPEG: ") + s.message);
    }
  }
  width = static_cast<int>(s.width);
  height = static_cast<int>(s.height);
  std::vector<std::uint8_t> out(s.pixels, s.pixels + static_cast<std::size_t>(s.width) * s.height * 3);
  std::free(s.pixels);
  return out;
}

}  // namespace tunnelmap
