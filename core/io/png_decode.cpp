#include "core/io/png_decode.h"

#include <png.h>

#include <csetjmp>
#include <cstring>

#include "core/util/error.h"

namespace tunnelmap {
namespace {

// What libpng said, and where it reads from. Plain data: libpng leaves by longjmp, which must
// not skip a C++ destructor, so nothing with one lives in the frames it unwinds.
struct PngSession {
  const std::uint8_t* data;
  std::size_t size;
  std::size_t pos;
  char error[200];
};

void on_error(png_structp png, png_const_charp message) {
  auto* s = static_cast<PngSession*>(png_get_error_ptr(png));
  std::snprintf(s->error, sizeof s->error, "%s", message ? message : "unknown error");
  png_longjmp(png, 1);
}

void on_warning(png_structp, png_const_charp) {}  // a warning decodes on; never on stderr

void read_bytes(png_structp png, png_bytep out, png_size_t n) {
  auto* s = static_cast<PngSession*>(png_get_io_ptr(png));
  if (n > s->size - s->pos) png_error(png, "file ends inside a chunk");
  std::memcpy(out, s->data + s->pos, n);
  s->pos += n;
}

enum class Target { Grey16, Rgb8 };

// The header's size into width/height, then (when `rows` is not null) the image into `rows`.
// Returns false with session.error set when libpng fails; `rows` must hold height rows of the
// target's width (the caller allocates them after a first call without rows).
bool run_libpng(PngSession& session, Target target, png_bytep* rows, png_uint_32& width, png_uint_32& height) {
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &session, on_error, on_warning);
  if (!png) return std::snprintf(session.error, sizeof session.error, "out of memory"), false;
  png_infop info = png_create_info_struct(png);
  if (!info || setjmp(png_jmpbuf(png))) {
    png_destroy_read_struct(&png, info ? &info : nullptr, nullptr);
    return false;
  }
  png_set_read_fn(png, &session, read_bytes);
  png_read_info(png, info);
  width = png_get_image_width(png, info);
  height = png_get_image_height(png, info);
  if (target == Target::Grey16) {
    if (png_get_bit_depth(png, info) != 16 || png_get_color_type(png, info) != PNG_COLOR_TYPE_GRAY)
      png_error(png, "not a 16-bit single-channel image");
    png_set_swap(png);  // PNG stores 16-bit samples big-endian
  } else {
    png_set_expand(png);
    png_set_strip_16(png);
    png_set_strip_alpha(png);
    png_set_gray_to_rgb(png);
  }
  png_set_interlace_handling(png);
  png_read_update_info(png, info);
  const png_size_t row_bytes = target == Target::Grey16 ? width * 2 : width * 3;
  if (png_get_rowbytes(png, info) != row_bytes) png_error(png, "unexpected row size after conversion");
  if (rows) {
    png_read_image(png, rows);
    png_read_end(png, nullptr);
  }
  png_destroy_read_struct(&png, &info, nullptr);
  return true;
}

// Two passes: the header, then the image into rows of `Pixel` x channels.
template <typename Pixel>
std::vector<Pixel> decode(const std::vector<std::uint8_t>& bytes, const std::string& path, Target target,
                          int channels, int& width, int& height) {
  PngSession session{bytes.data(), bytes.size(), 0, {}};
  png_uint_32 w = 0, h = 0;
  if (!run_libpng(session, target, nullptr, w, h)) throw InputError(path, std::string("corrupt PNG: ") + session.error);
  std::vector<Pixel> pixels(static_cast<std::size_t>(w) * h * channels);
  std::vector<png_bytep> rows(h);
  for (png_uint_32 v = 0; v < h; ++v)
    rows[v] = reinterpret_cast<png_bytep>(pixels.data() + static_cast<std::size_t>(v) * w * channels);
  session = PngSession{bytes.data(), bytes.size(), 0, {}};
  if (!run_libpng(session, target, rows.data(), w, h)) throw InputError(path, std::string("corrupt PNG: ") + session.error);
  width = static_cast<int>(w);
  height = static_cast<int>(h);
  return pixels;
}

}  // namespace

std::vector<std::uint16_t> decode_png_grey16(const std::vector<std::uint8_t>& bytes, const std::string& path,
                                             int& width, int& height) {
  return decode<std::uint16_t>(bytes, path, Target::Grey16, 1, width, height);
}

std::vector<std::uint8_t> decode_png_rgb8(const std::vector<std::uint8_t>& bytes, const std::string& path,
                                          int& width, int& height) {
  return decode<std::uint8_t>(bytes, path, Target::Rgb8, 3, width, height);
}

}  // namespace tunnelmap
