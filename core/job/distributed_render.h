#pragma once

#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include "core/job/render_job.h"

namespace caustica {

// Whether this process is one rank of a job that mpirun started (Open MPI
// sets OMPI_COMM_WORLD_SIZE, PMIx launchers PMIX_RANK).
inline bool started_by_mpirun() { return std::getenv("OMPI_COMM_WORLD_SIZE") || std::getenv("PMIX_RANK"); }

// MPI from initialisation to finalisation, around one render. Throws
// std::runtime_error where caustica was built without MPI.
class RankSession {
 public:
  RankSession();
  ~RankSession();
  RankSession(const RankSession&) = delete;
  RankSession& operator=(const RankSession&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }
  // The job's ranks on this rank's machine, which share its cores.
  int local_size() const { return local_size_; }
  // Ends every rank of the job now, with `code`.
  [[noreturn]] void abort(int code) const;

 private:
  int rank_ = 0, size_ = 1, local_size_ = 1;
};

struct DistributedOptions {
  // Seconds a rank may stay silent, beyond what rank 0's own share of a
  // round took, before it counts as lost.
  double rank_timeout = 120;
};

// What rank 0 holds once the ranks are done.
struct DistributedRender {
  // The film of every sample rank 0 received; its stats count them, with
  // the ranks and (where ranks were lost) the ranges the samples cover.
  RenderResult result;
  // Ranks that stopped answering: the samples they had not yet sent are
  // missing from the film.
  std::vector<int> lost;
  // A signal (mpirun ending the job, as it does when a rank dies or on
  // Ctrl-C) stopped rank 0 part-way: the film holds what was collected
  // before, and the process must end, without unwinding (its own share
  // may still be rendering on another thread), once the film is written.
  bool signalled = false;
};

// Renders the job across the session's ranks; every rank calls it. Each
// round of passes is cut into contiguous shares of its sample indices
// (rank_share), every rank renders its share into a film of its own, and
// rank 0 adds the films it collects every few seconds: the film's sums are
// exact, so the result is the single-process render of the same seed and
// samples bit for bit, for any number of ranks. Rank 0 decides every
// round (sample count, time budget, interrupts), so all ranks stop at the
// same sample count. An integrator whose samples do not split (sppm)
// renders on rank 0 alone. Returns the render on rank 0, nothing on the
// other ranks.
std::optional<DistributedRender> render_across_ranks(const RenderJob& job, const RankSession& session,
                                                     RenderProgress* progress, const DistributedOptions& options);

// What the plan says of a render across `ranks` ranks with this job.
std::string distributed_plan(const RenderJob& job, int ranks);

}  // namespace caustica
