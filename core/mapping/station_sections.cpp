#include "core/mapping/station_sections.h"

#include <cmath>

#include "core/util/median.h"

namespace tunnelmap {

namespace {

// Differs by more than `change` where both are known.
bool differs(double a, double b, double change) {
  return !std::isnan(a) && !std::isnan(b) && std::abs(a - b) > change;
}

bool measured(double w, double h) { return !std::isnan(w) || !std::isnan(h); }

}  // namespace

SectionSplit split_sections(const std::vector<double>& w, const std::vector<double>& h,
                            double change, int min_run) {
  const int n = static_cast<int>(w.size());
  SectionSplit out;
  out.outlier.assign(w.size(), false);
  if (n == 0) return out;
  std::vector<double> sec_w, sec_h;  // accepted values of the current section
  int first = 0;
  const auto close = [&](int last) {
    out.sections.push_back({first, last, median_of_measured(sec_w), median_of_measured(sec_h)});
    sec_w.clear();
    sec_h.clear();
  };
  int k = 0;
  while (k < n) {
    const double ref_w = median_of_measured(sec_w), ref_h = median_of_measured(sec_h);
    if (!measured(w[k], h[k]) ||
        !(differs(w[k], ref_w, change) || differs(h[k], ref_h, change))) {
      if (!std::isnan(w[k])) sec_w.push_back(w[k]);
      if (!std::isnan(h[k])) sec_h.push_back(h[k]);
      ++k;
      continue;
    }
    // A run of stations that differ from the section and agree with each other.
    std::vector<double> run_w, run_h;
    std::vector<int> run;
    int j = k;
    for (; j < n; ++j) {
      if (!measured(w[j], h[j])) continue;
      const bool off = differs(w[j], ref_w, change) || differs(h[j], ref_h, change);
      const bool agrees = !differs(w[j], median_of_measured(run_w), change) && !differs(h[j], median_of_measured(run_h), change);
      if (!off || !agrees) break;
      run.push_back(j);
      if (!std::isnan(w[j])) run_w.push_back(w[j]);
      if (!std::isnan(h[j])) run_h.push_back(h[j]);
    }
    if (static_cast<int>(run.size()) >= min_run) {
      close(k - 1);
      first = k;
      sec_w = run_w;
      sec_h = run_h;
    } else {
      for (int r : run) out.outlier[static_cast<std::size_t>(r)] = true;
    }
    k = run.empty() ? k + 1 : run.back() + 1;
  }
  close(n - 1);
  return out;
}

}  // namespace tunnelmap
