#include "core/sampling/sampler.h"

#include "core/registry/properties.h"

namespace caustica {

uint32_t read_sample_count(const Properties& props) {
  const int64_t n = props.get_int("sample_count");
  if (n <= 0 || n > (int64_t(1) << 32) - 1) throw props.error("sample_count", "must be a positive 32-bit count");
  return uint32_t(n);
}

}  // namespace caustica
