#include "core/planes/polygon_simplify.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <utility>

namespace tunnelmap {

namespace {

// The first index of the largest positive score(i) over `count` indices of a cycle of `n`
// from `first` on (in two straight runs, no wrap test per index); -1 if none is positive.
template <class Score>
int first_cyclic_max(int n, int first, int count, Score score, std::int64_t& best) {
  best = 0;
  int arg = -1;
  const int run = std::min(count, n - first);
  for (int i = first; i < first + run; ++i) {
    const std::int64_t v = score(i);
    if (v > best) best = v, arg = i;
  }
  for (int i = 0; i < count - run; ++i) {
    const std::int64_t v = score(i);
    if (v > best) best = v, arg = i;
  }
  return arg;
}

}  // namespace

void simplify_closed_polygon(const std::vector<PixelPoint>& polygon, double tolerance, std::vector<PixelPoint>& out) {
  SimplifyScratch scratch;
  simplify_closed_polygon(polygon, tolerance, out, scratch);
}

void simplify_closed_polygon(const std::vector<PixelPoint>& polygon, double tolerance, std::vector<PixelPoint>& out,
                             SimplifyScratch& scratch) {
  out.clear();
  const int n = static_cast<int>(polygon.size());
  if (n == 0) return;
  const PixelPoint* p = polygon.data();
  const double eps2 = tolerance * tolerance;
  const auto next = [n](int i) { return i + 1 == n ? 0 : i + 1; };

  // 1. Two vertices far apart: three times, jump to the vertex farthest from the current one
  // (the first of equals; if all coincide the previous jump repeats, as in OpenCV).
  int start = 0, far_offset = 0;
  std::int64_t far_d2 = 0;
  for (int pass = 0; pass < 3; ++pass) {
    start += far_offset;
    if (start >= n) start -= n;
    const PixelPoint o = p[start];
    const int far = first_cyclic_max(n, next(start), n - 1, [p, o](int i) {
      const std::int64_t dx = p[i].x - o.x, dy = p[i].y - o.y;
      return dx * dx + dy * dy;
    }, far_d2);
    if (far >= 0) far_offset = far > start ? far - start : far - start + n;
  }
  if (static_cast<double>(far_d2) <= eps2) {
    out.push_back(p[start]);
    return;
  }

  // 2. Douglas-Peucker on both halves, depth first, first half first: a chord whose inner
  // vertices all lie within the tolerance of its line keeps only its first vertex, otherwise
  // it is split at the farthest (first of equals) inner vertex. Exact integer distances.
  std::vector<std::pair<int, int>>& stack = scratch.stack;
  stack.clear();
  const int far = start + far_offset < n ? start + far_offset : start + far_offset - n;
  stack.emplace_back(far, start);
  stack.emplace_back(start, far);
  while (!stack.empty()) {
    const auto [a, b] = stack.back();
    stack.pop_back();
    const PixelPoint o = p[a];
    const std::int64_t dx = p[b].x - o.x, dy = p[b].y - o.y;
    const int inner = (b > a ? b - a : b - a + n) - 1;
    std::int64_t max_d = 0;  // |cross| = distance to the line times the chord's length
    const int split = first_cyclic_max(n, next(a), inner, [p, o, dx, dy](int i) {
      return std::abs((p[i].y - o.y) * dx - (p[i].x - o.x) * dy);
    }, max_d);
    const double md = static_cast<double>(max_d);
    if (md * md <= eps2 * static_cast<double>(dx * dx + dy * dy)) {
      out.push_back(o);
    } else {
      stack.emplace_back(split, b);
      stack.emplace_back(a, split);
    }
  }

  // 3. One cyclic pass over the result, in place: a vertex between two diagonal neighbours
  // (neither chord axis-parallel) that lies within tolerance/sqrt(2) of their chord and
  // between them is dropped, and then the vertex after it is not examined.
  const int count = static_cast<int>(out.size());
  if (count <= 2) return;
  const auto wrap = [count](int i) { return i + 1 == count ? 0 : i + 1; };
  int kept = count;
  int pos = 0, wpos = 0;
  PixelPoint prev = out[count - 1];
  PixelPoint cur = out[pos];
  pos = wrap(pos);
  for (int i = 0; i < count && kept > 2; ++i) {
    const PixelPoint end = out[pos];
    pos = wrap(pos);
    const double dx = end.x - prev.x, dy = end.y - prev.y;
    const double ux = cur.x - prev.x, uy = cur.y - prev.y;
    const double dist = std::fabs(ux * dy - uy * dx);
    const double along = ux * (end.x - cur.x) + uy * (end.y - cur.y);
    if (dist * dist <= 0.5 * eps2 * (dx * dx + dy * dy) && dx != 0 && dy != 0 && along >= 0) {
      --kept;
      out[wpos] = prev = end;
      wpos = wrap(wpos);
      cur = out[pos];
      pos = wrap(pos);
      ++i;
      continue;
    }
    out[wpos] = prev = cur;
    wpos = wrap(wpos);
    cur = end;
  }
  out.resize(kept);
}

}  // namespace tunnelmap
