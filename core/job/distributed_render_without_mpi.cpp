// The distributed render where caustica was built without MPI: a process
// that mpirun started says so instead of rendering the whole image once per
// rank.

#include <cstdlib>
#include <stdexcept>

#include "core/job/distributed_render.h"

namespace caustica {

RankSession::RankSession() {
  throw std::runtime_error(
      "this caustica was built without MPI, so mpirun would make each rank render the whole image: install "
      "libopenmpi-dev (scripts/install-deps.sh does) and build again");
}

RankSession::~RankSession() = default;

void RankSession::abort(int code) const { std::_Exit(code); }

std::optional<DistributedRender> render_across_ranks(const RenderJob&, const RankSession&, RenderProgress*,
                                                     const DistributedOptions&) {
  return std::nullopt;
}

std::string distributed_plan(const RenderJob&, int) { return ""; }

}  // namespace caustica
