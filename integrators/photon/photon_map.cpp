#include "integrators/photon/photon_map.h"

#include <bit>
#include <stdexcept>

namespace caustica {

void PhotonMap::build(std::span<const Photon> photons, float radius) {
  if (!(radius > 0)) throw std::invalid_argument("photon map radius must be positive");
  radius_ = radius;
  inv_cell_ = 1 / radius;
  const uint32_t buckets = std::bit_ceil(uint32_t(std::max<size_t>(2 * photons.size(), 1)));
  mask_ = buckets - 1;
  // A counting sort by bucket keeps the photons' order within each bucket,
  // so the map (and every sum over it) is the same for any thread count.
  start_.assign(buckets + 1, 0);
  std::vector<uint32_t>& bucket_of = bucket_of_;
  bucket_of.resize(photons.size());
  for (size_t i = 0; i < photons.size(); ++i) {
    const Vec3& p = photons[i].p;
    bucket_of[i] = bucket(cell(p.x), cell(p.y), cell(p.z));
    ++start_[bucket_of[i] + 1];
  }
  for (uint32_t b = 0; b < buckets; ++b) start_[b + 1] += start_[b];
  std::vector<uint32_t>& next = next_;
  next.assign(start_.begin(), start_.end() - 1);
  photons_.resize(photons.size());
  for (size_t i = 0; i < photons.size(); ++i) photons_[next[bucket_of[i]]++] = photons[i];
}

}  // namespace caustica
