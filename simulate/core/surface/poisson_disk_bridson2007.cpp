#include "surface/poisson_disk_bridson2007.h"

#include <algorithm>
#include <random>

#include "surface/point_hash_grid.h"

namespace dp {

namespace {

// Uniform numbers from mt19937's raw output, not std::uniform_*_distribution,
// whose algorithms differ between standard libraries: the samples must be
// the same wherever the set-up runs.
class Random {
 public:
  explicit Random(std::uint32_t seed) : engine_(seed) {}
  double uniform() { return (engine_() >> 5) * (1.0 / 134217728.0); }  // [0, 1), 27 bits
  std::size_t below(std::size_t n) { return static_cast<std::size_t>(uniform() * static_cast<double>(n)); }

 private:
  std::mt19937 engine_;
};

class Sampler {
 public:
  Sampler(const std::vector<Vec3>& position, const std::vector<float>& area, const PoissonDiskSettings& s)
      : x_(position), area_(area), s_(s), r2_(s.radius * s.radius), texels_(2 * s.radius), samples_(s.radius),
        random_(s.seed) {
    for (std::size_t t = 0; t < x_.size(); ++t) texels_.insert(x_[t], static_cast<std::uint32_t>(t));
  }

  std::vector<std::uint32_t> run() {
    // Starts in a random order, so no chart or corner is favoured.
    std::vector<std::uint32_t> order(x_.size());
    for (std::size_t t = 0; t < order.size(); ++t) order[t] = static_cast<std::uint32_t>(t);
    for (std::size_t i = order.size(); i > 1; --i) std::swap(order[i - 1], order[random_.below(i)]);
    for (std::uint32_t t : order)
      if (area_[t] > 0 && far_from_samples(x_[t])) {
        add(t);
        grow();
      }
    return chosen_;
  }

 private:
  bool far_from_samples(Vec3 p) const {
    bool far = true;
    samples_.for_each_near(p, s_.radius, [&](std::uint32_t k) { far = far && length_squared(x_[chosen_[k]] - p) >= r2_; });
    return far;
  }

  void add(std::uint32_t texel) {
    samples_.insert(x_[texel], static_cast<std::uint32_t>(chosen_.size()));
    chosen_.push_back(texel);
    active_.push_back(texel);
  }

  // Bridson's loop: a random active sample tries up to k candidates from its
  // annulus; it leaves the active list when all k fail. A sample that
  // succeeds tries again at once (Bridson picks the next sample at random;
  // staying reuses the annulus, which is most of the cost on a fine texture,
  // and changes neither the minimum distance nor the stopping rule).
  void grow() {
    std::vector<std::uint32_t> annulus;
    std::vector<double> cumulative_area;
    while (!active_.empty()) {
      const std::size_t a = random_.below(active_.size());
      const Vec3 centre = x_[active_[a]];
      annulus.clear();
      cumulative_area.clear();
      double total = 0;
      texels_.for_each_near(centre, 2 * s_.radius, [&](std::uint32_t t) {
        const float d2 = length_squared(x_[t] - centre);
        if (d2 >= r2_ && d2 < 4 * r2_ && area_[t] > 0) {
          total += area_[t];
          annulus.push_back(t);
          cumulative_area.push_back(total);
        }
      });
      bool placed = true;
      while (placed) {
        placed = false;
        for (int k = 0; k < s_.attempts && !annulus.empty() && !placed; ++k) {
          const double pick = random_.uniform() * total;
          const std::size_t i = std::upper_bound(cumulative_area.begin(), cumulative_area.end(), pick) - cumulative_area.begin();
          const std::uint32_t candidate = annulus[std::min(i, annulus.size() - 1)];
          if (far_from_samples(x_[candidate])) {
            add(candidate);
            placed = true;
          }
        }
      }
      active_[a] = active_.back();
      active_.pop_back();
    }
  }

  const std::vector<Vec3>& x_;
  const std::vector<float>& area_;
  PoissonDiskSettings s_;
  float r2_;
  PointHashGrid texels_, samples_;
  Random random_;
  std::vector<std::uint32_t> chosen_, active_;
};

}  // namespace

std::vector<std::uint32_t> poisson_disk_samples(const std::vector<Vec3>& position, const std::vector<float>& area,
                                                const PoissonDiskSettings& settings) {
  return Sampler(position, area, settings).run();
}

}  // namespace dp
