#include "core/planes/boundary_trace.h"

#include <emmintrin.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <utility>

namespace tunnelmap {

namespace {

// Chain codes: 0 = right, counter-clockwise on screen (y down), 2 = up, 4 = left, 6 = down.
constexpr int kDx[8] = {1, 1, 0, -1, -1, -1, 0, 1};
constexpr int kDy[8] = {0, -1, -1, -1, 0, 1, 1, 1};

// Mask values: background, foreground not on a traced border, and Suzuki and Abe's two
// border marks: a traced pixel whose right neighbour is background seen by the trace (the
// border's right side, their -NBD), and any other traced pixel (+NBD).
constexpr std::uint8_t kBackground = 0, kForeground = 1, kLeftSide = 2, kRightSide = 4;

// The box, framed by one background pixel on every side (mask coordinates = box + 1): a byte
// per pixel for the tracer's neighbour lookups (no bounds checks) and its marks, and one bit
// per pixel, 64 to a word, of the foreground and of the traced border pixels for the scan.
struct BoxMask {
  std::uint8_t* bytes;
  int stride;  // bytes per row
  std::uint64_t* foreground;
  std::uint64_t* traced;
  int words;   // words per row

  void mark_traced(int x, int y) const { traced[y * words + (x >> 6)] |= 1ull << (x & 63); }
};

using Chain = BoundaryTraceScratch::Chain;

// Follows the border through (x, y) (foreground, background on its left), marking every
// pixel it passes. Moore-neighbour tracing with the neighbour order and stopping rule of
// Suzuki and Abe's border following (OpenCV's): the first move goes to the first foreground
// neighbour clockwise from the upper left; each later search turns counter-clockwise from
// the pixel we came from; the trace ends when it is about to repeat its first move. Writes
// the pixels where the direction changes (CHAIN_APPROX_SIMPLE), shifted by `origin`, and
// returns twice the signed shoelace area.
std::int64_t follow_border(const BoxMask& box, int x, int y, const int (&offset)[16], PixelPoint origin,
                           Chain& out) {
  // Plain locals in the loop (no vector bookkeeping through the Chain reference).
  PixelPoint* points = out.points.data();
  int count = 0, room = static_cast<int>(out.points.size());
  const auto emit = [&](int px, int py) {
    if (count == room) {
      out.points.resize(std::max(64, 2 * room));
      points = out.points.data();
      room = static_cast<int>(out.points.size());
    }
    points[count].x = px + origin.x;
    points[count].y = py + origin.y;
    ++count;
  };
  std::uint8_t* const i0 = box.bytes + static_cast<std::size_t>(y) * box.stride + x;
  int s = 4;
  std::uint8_t* i1;
  do {
    s = (s - 1) & 7;
    i1 = i0 + offset[s];
  } while (*i1 == kBackground && s != 4);
  if (s == 4) {  // an isolated pixel
    *i0 = kRightSide;
    box.mark_traced(x, y);
    emit(x, y);
    out.count = count;
    return 0;
  }
  std::uint8_t* i3 = i0;
  int prev_s = s ^ 4;  // the closing move (i1 -> i0) decides whether i0 is a corner
  std::int64_t twice_area = 0;
  for (;;) {
    // Turn counter-clockwise from the way back (s) to the next foreground neighbour; the way
    // back itself is foreground, so one is found. Branch-free: the eight neighbours as bits.
    const int back = s;
    unsigned around = 0;
    for (int d = 0; d < 8; ++d) around |= static_cast<unsigned>(i3[offset[d]] != kBackground) << d;
    s = (back + 1 + __builtin_ctz((around | around << 8) >> (back + 1))) & 7;
    std::uint8_t* const i4 = i3 + offset[s];
    if (static_cast<unsigned>(s - 1) < static_cast<unsigned>(back)) {
      *i3 = kRightSide;  // the search passed direction 0 (right) and found background there
    } else if (*i3 == kForeground) {
      *i3 = kLeftSide;
    }
    box.mark_traced(x, y);
    if (s != prev_s) {
      emit(x, y);
      prev_s = s;
    }
    twice_area += static_cast<std::int64_t>(x) * kDy[s] - static_cast<std::int64_t>(y) * kDx[s];
    x += kDx[s];
    y += kDy[s];
    if (i4 == i0 && i3 == i1) break;
    i3 = i4;
    s = (s + 4) & 7;
  }
  out.count = count;
  return twice_area;
}

// Fills `box` from the labels, in the scratch's storage that only grows.
BoxMask fill_box(const std::int32_t* labels, int width, std::int32_t label, int u0, int v0, int bw, int bh,
                 BoundaryTraceScratch& scratch) {
  std::vector<std::uint8_t>& bytes = scratch.bytes;
  std::vector<std::uint64_t>& foreground = scratch.foreground;
  std::vector<std::uint64_t>& traced = scratch.traced;
  BoxMask box{};
  box.stride = bw + 2;
  box.words = (box.stride + 63) / 64;
  const std::size_t rows = static_cast<std::size_t>(bh) + 2;
  // 64 spare bytes: the bit rows are built from whole 64-byte blocks.
  if (bytes.size() < rows * box.stride + 64) bytes.resize(rows * box.stride + 64);
  if (foreground.size() < rows * box.words) foreground.resize(rows * box.words);
  if (traced.size() < rows * box.words) traced.resize(rows * box.words);
  box.bytes = bytes.data();
  box.foreground = foreground.data();
  box.traced = traced.data();
  std::memset(box.bytes, kBackground, box.stride);
  std::memset(box.bytes + (rows - 1) * box.stride, kBackground, box.stride);
  std::memset(box.traced, 0, rows * box.words * sizeof(std::uint64_t));
  const int tail = box.stride - 64 * (box.words - 1);  // valid bits in a row's last word
  const std::uint64_t tail_mask = tail == 64 ? ~0ull : (1ull << tail) - 1;
  for (int y = 1; y <= bh; ++y) {
    const std::int32_t* in = labels + static_cast<std::size_t>(y - 1 + v0) * width + u0;
    std::uint8_t* row = box.bytes + static_cast<std::size_t>(y) * box.stride;
    row[0] = row[bw + 1] = kBackground;
    for (int x = 0; x < bw; ++x) row[x + 1] = in[x] == label ? kForeground : kBackground;
    // Bit 0 of each byte, 16 at a time (shifted into the byte's sign bit for movemask).
    std::uint64_t* bits = box.foreground + static_cast<std::size_t>(y) * box.words;
    for (int w = 0; w < box.words; ++w) {
      std::uint64_t word = 0;
      for (int q = 0; q < 4; ++q) {
        const __m128i v = _mm_loadu_si128(reinterpret_cast<const __m128i*>(row + 64 * w + 16 * q));
        word |= static_cast<std::uint64_t>(static_cast<std::uint32_t>(_mm_movemask_epi8(_mm_slli_epi16(v, 7))))
                << (16 * q);
      }
      bits[w] = word;
    }
    bits[box.words - 1] &= tail_mask;  // the bytes read past the row's end
  }
  return box;
}

}  // namespace

std::int64_t twice_polygon_area(const std::vector<PixelPoint>& polygon) {
  std::int64_t a = 0;
  for (std::size_t i = 0, n = polygon.size(); i < n; ++i) {
    const PixelPoint& p = polygon[i];
    const PixelPoint& q = polygon[(i + 1) % n];
    a += static_cast<std::int64_t>(p.x) * q.y - static_cast<std::int64_t>(q.x) * p.y;
  }
  return std::abs(a);
}

std::int64_t trace_largest_outer_boundary(const std::int32_t* labels, int width, std::int32_t label, int u0,
                                          int v0, int u1, int v1, std::vector<PixelPoint>& contour) {
  BoundaryTraceScratch scratch;
  return trace_largest_outer_boundary(labels, width, label, u0, v0, u1, v1, contour, scratch);
}

std::int64_t trace_largest_outer_boundary(const std::int32_t* labels, int width, std::int32_t label, int u0,
                                          int v0, int u1, int v1, std::vector<PixelPoint>& contour,
                                          BoundaryTraceScratch& scratch) {
  contour.clear();
  const int bw = u1 - u0 + 1, bh = v1 - v0 + 1;
  if (bw <= 0 || bh <= 0) return 0;
  const BoxMask box = fill_box(labels, width, label, u0, v0, bw, bh, scratch);
  int offset[16];
  for (int s = 0; s < 16; ++s) offset[s] = kDx[s & 7] + kDy[s & 7] * box.stride;
  const PixelPoint origin{u0 - 1, v0 - 1};  // mask to image coordinates
  Chain& trace = scratch.trace;
  Chain& best = scratch.best;
  best.count = 0;
  std::int64_t best_area = -1;

  // Suzuki and Abe's raster scan for outer borders only (OpenCV's RETR_EXTERNAL): an
  // untraced foreground pixel with background on its left starts a border, unless the
  // nearest traced pixel to its left in the row is a left-side one: then it lies inside a
  // traced component, on a hole's border or on a component in a hole, which enclose less
  // than the border around them. So the traced borders, their order and the pick are OpenCV's.
  for (int y = 1; y <= bh; ++y) {
    const std::uint64_t* fg = box.foreground + static_cast<std::size_t>(y) * box.words;
    const std::uint64_t* traced = box.traced + static_cast<std::size_t>(y) * box.words;
    const std::uint8_t* row = box.bytes + static_cast<std::size_t>(y) * box.stride;
    std::uint64_t carry = 0;  // foreground bit of the previous word's last pixel
    // The nearest traced pixel left of the scan (0: the frame, background) and how far the
    // row's traced bits have been looked at. A trace started at x marks x, so bits it adds
    // left of x never matter.
    int last_traced = 0, seen = 0;
    for (int w = 0; w < box.words; ++w) {
      std::uint64_t starts = fg[w] & ~(fg[w] << 1 | carry);
      carry = fg[w] >> 63;
      // traced[w] is reread: each trace may mark pixels further along this row.
      for (std::uint64_t todo; (todo = starts & ~traced[w]) != 0;) {
        const int bit = __builtin_ctzll(todo);
        const int x = 64 * w + bit;
        starts &= bit == 63 ? 0 : ~0ull << (bit + 1);
        for (int sw = seen >> 6; sw <= w; ++sw) {  // traced bits in [seen, x)
          std::uint64_t bits = traced[sw];
          if (sw == seen >> 6) bits &= ~0ull << (seen & 63);
          if (sw == w) bits &= (1ull << bit) - 1;
          if (bits != 0) last_traced = 64 * sw + 63 - __builtin_clzll(bits);
        }
        seen = x;
        if (row[last_traced] == kLeftSide) continue;
        last_traced = x;
        seen = x + 1;
        const std::int64_t area = std::abs(follow_border(box, x, y, offset, origin, trace));
        if (area >= best_area) {  // ties: the later one, like OpenCV's bottom-up contour list
          best_area = area;
          std::swap(trace, best);
        }
      }
    }
  }
  contour.assign(best.points.begin(), best.points.begin() + best.count);
  return std::max<std::int64_t>(best_area, 0);
}

}  // namespace tunnelmap
