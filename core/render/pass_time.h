#pragma once

#include <cstdint>

namespace caustica {

// The time (see Ray::time) of every path in pass `pass` of a render with
// `seed`, for the integrators whose passes share their photons among all
// pixels (photon, sppm, vcm): a photon and the camera path that gathers it
// must meet the scene as it stands at one instant. Successive passes fill
// the shutter evenly (the base-2 radical inverse of the pass number: after
// 2^k passes, one in each of 2^k equal intervals), all shifted by a
// fraction the seed decides, so that renders with other seeds are
// independent estimates of the average over the shutter.
float pass_time(uint64_t pass, uint64_t seed);

}  // namespace caustica
