#pragma once

#include <tbb/enumerable_thread_specific.h>

#include <vector>

#include "core/geometry/ray.h"

namespace caustica {

// The rays a render asks the scene about, recorded so that a benchmark can
// replay exactly the same queries against Embree alone. Recording is safe
// from many threads; read the log once the render is over.
class RayLog {
 public:
  struct Entry {
    Ray ray;
    bool shadow;  // an occlusion query; otherwise a closest-hit one
  };

  void record(const Ray& ray, bool shadow) { per_thread_.local().push_back({ray, shadow}); }
  // Every thread's rays, one thread's after another.
  std::vector<Entry> entries() const {
    std::vector<Entry> all;
    for (const auto& rays : per_thread_) all.insert(all.end(), rays.begin(), rays.end());
    return all;
  }

 private:
  tbb::enumerable_thread_specific<std::vector<Entry>> per_thread_;
};

}  // namespace caustica
