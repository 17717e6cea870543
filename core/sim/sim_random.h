#pragma once
// Random numbers for the simulator: std::mt19937 streams seeded from (seed, frame, stream) and
// our own uniform/normal conversions, because the std:: distributions differ between standard
// libraries and a dataset must be reproducible bit for bit from its seed.
#include <cmath>
#include <cstdint>
#include <random>

namespace tunnelmap::sim {

class SimRandom {
 public:
  SimRandom(unsigned seed, std::uint32_t a, std::uint32_t b) {
    std::seed_seq seq{static_cast<std::uint32_t>(seed), a, b, 0x7011a9u};
    rng_.seed(seq);
  }
  // Uniform in (0, 1).
  double uniform() { return (static_cast<double>(rng_()) + 0.5) * (1.0 / 4294967296.0); }
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  // Standard normal (Box-Muller, both values used).
  double normal() {
    if (has_spare_) {
      has_spare_ = false;
      return spare_;
    }
    const double r = std::sqrt(-2.0 * std::log(uniform()));
    const double phi = 6.283185307179586 * uniform();
    spare_ = r * std::sin(phi);
    has_spare_ = true;
    return r * std::cos(phi);
  }
  std::uint32_t bits() { return rng_(); }

 private:
  std::mt19937 rng_;
  double spare_ = 0.0;
  bool has_spare_ = false;
};

// Stream tags so that independent uses of one seed never share a sequence.
constexpr std::uint32_t kStreamGeometry = 0x47454f4du;  // rust patches, roughness hash
constexpr std::uint32_t kStreamPose = 0x504f5345u;      // per-frame pose jitter
constexpr std::uint32_t kStreamDrift = 0x44524654u;     // odometry drift, group by group
constexpr std::uint32_t kStreamRowBase = 0x10000u;      // + row index: per-row sensor noise
constexpr std::uint32_t kStreamFlyingBase = 0x20000u;   // + row index: ToF flying pixels

}  // namespace tunnelmap::sim
