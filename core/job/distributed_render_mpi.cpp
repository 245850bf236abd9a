// The distributed render over MPI (Open MPI); built where CMake finds MPI.

#include <mpi.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdlib>
#include <stdexcept>
#include <thread>

#include "core/job/distributed_render.h"
#include "core/job/rank_shares.h"
#include "core/job/sample_ranges.h"
#include "core/render/pass_schedule.h"
#include "core/scene/scene.h"

namespace caustica {

RankSession::RankSession() {
  int provided = 0;
  // Only the main thread of a rank calls MPI.
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  MPI_Comm local;
  MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, rank_, MPI_INFO_NULL, &local);
  MPI_Comm_size(local, &local_size_);
  MPI_Comm_free(&local);
}

RankSession::~RankSession() { MPI_Finalize(); }

void RankSession::abort(int code) const {
  MPI_Abort(MPI_COMM_WORLD, code);
  std::_Exit(code);
}

namespace {

enum Tag : int { kHello = 1, kOrder, kReport, kFilm };

// Rank 0's word to the other ranks before each round.
struct Order {
  uint64_t first = 0, count = 0, round = 0;
  int32_t collect = 0;  // send the film rendered since the last collection first
  int32_t stop = 0;     // then end
};

// A rank's word after its share of a round.
struct Report {
  uint64_t first = 0, count = 0;  // the samples it rendered
  uint64_t rays = 0;
};

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// What every rank must agree on to render parts of one image.
std::string description(const RenderJob& job) {
  const Film& film = *job.scene()->sensor().film();
  const RenderSettings& s = job.settings();
  return job.integrator().describe() + " | film " + std::to_string(film.width()) + "x" + std::to_string(film.height()) +
         " | seed " + std::to_string(s.seed) + " | first sample " + std::to_string(s.first_sample) + " | spp " +
         std::to_string(s.spp) + " | time " + std::to_string(s.time_limit);
}

// Waits for a message from `source` with `tag`; its size in `type` units,
// or -1 if `deadline` passed or `stop` turned true first.
int wait_for(int source, int tag, MPI_Datatype type, Clock::time_point deadline, const std::atomic<bool>* stop) {
  for (;;) {
    int ready = 0;
    MPI_Status status;
    MPI_Iprobe(source, tag, MPI_COMM_WORLD, &ready, &status);
    if (ready) {
      int count = 0;
      MPI_Get_count(&status, type, &count);
      return count;
    }
    if (Clock::now() > deadline || (stop && stop->load())) return -1;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
}

void send_bytes(const void* data, size_t size, int to, int tag) {
  MPI_Send(data, int(size), MPI_BYTE, to, tag, MPI_COMM_WORLD);
}

// Renders `share` of the samples, pass by pass, into `film`; false if a
// pass was stopped.
bool render_share(IntegratorRun& run, IndexRange share, const PassTarget& target) {
  const uint32_t max_pass = std::max(1u, run.max_pass_samples());
  for (uint64_t next = share.first, end = share.first + share.count; next < end;) {
    const Pass pass = pass_containing(next, max_pass);
    const uint32_t count = uint32_t(std::min(pass.first + pass.count, end) - next);
    if (!run.run_pass({pass.number, next, count}, target)) return false;
    next += count;
  }
  return true;
}

FilmBuffer fresh_film(const RenderJob& job) {
  const Film& film = *job.scene()->sensor().film();
  return FilmBuffer(film.width(), film.height(), job.integrator().channels());
}

int thread_count(const RenderJob& job) {
  const int threads = job.settings().threads;
  return threads > 0 ? threads : tbb::this_task_arena::max_concurrency();
}

// A rank other than 0: renders the shares rank 0 orders and sends back its
// reports and, when asked, its film.
void serve(const RenderJob& job, IntegratorRun& run, int rank, int ranks) {
  const Scene& scene = *job.scene();
  tbb::task_arena arena(thread_count(job));
  FilmBuffer film = fresh_film(job);
  for (;;) {
    Order order;
    MPI_Recv(&order, sizeof order, MPI_BYTE, 0, kOrder, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    if (order.collect) {
      const std::vector<double> packed = film.pack();
      MPI_Send(packed.data(), int(packed.size()), MPI_DOUBLE, 0, kFilm, MPI_COMM_WORLD);
      film.clear();
    }
    if (order.stop) return;
    const IndexRange share = rank_share({order.first, order.count}, rank, ranks, order.round);
    const uint64_t rays_before = scene.rays_traced();
    const PassTarget target{film, nullptr, thread_count(job), nullptr};
    arena.execute([&] { render_share(run, share, target); });
    const Report report{share.first, share.count, scene.rays_traced() - rays_before};
    send_bytes(&report, sizeof report, 0, kReport);
  }
}

// Rank 0: orders the rounds, renders its own shares, collects the others'.
class Coordinator {
 public:
  Coordinator(const RenderJob& job, std::shared_ptr<IntegratorRun> run, int ranks, RenderProgress* progress,
              const DistributedOptions& options)
      : job_(job),
        run_(std::move(run)),
        ranks_(ranks),
        progress_(progress),
        options_(options),
        out_{{fresh_film(job), {}}, {}, false},
        pending_(size_t(ranks)),
        live_(size_t(ranks), true) {}

  DistributedRender run() {
    const Scene& scene = *job_.scene();
    const Film& film = *scene.sensor().film();
    const RenderSettings& settings = job_.settings();
    const bool timed = settings.time_limit > 0;
    const uint64_t target = timed ? 0 : (settings.spp > 0 ? settings.spp : scene.sensor().sampler()->sample_count());
    const uint64_t pixels = uint64_t(film.width()) * film.height();
    if (progress_) progress_->pixel_samples_target = target * pixels;
    const uint32_t max_pass = std::max(1u, run_->max_pass_samples());
    uint64_t done = 0, round = 0, rays = 0, last_count = 1;
    double last_round = 0;
    Clock::time_point last_collect = Clock::now();
    double collect_cost = 0;
    const auto stopped = [&] { return settings.stop && settings.stop->load(); };
    while (!out_.signalled && out_.lost.empty()) {
      // A stop under mpirun is mpirun ending the job (or someone signalling
      // rank 0): the other ranks cannot be counted on to answer.
      if (stopped()) {
        out_.signalled = true;
        break;
      }
      if (done > 0 && !timed && done >= target) break;
      // A round gives every rank as many samples, doubling from one to the
      // integrator's largest pass (small rounds first let progress and time
      // budgets react quickly); a tail of less than one sample a rank joins
      // the last round.
      const uint64_t next = settings.first_sample + done;
      uint64_t count = uint64_t(ranks_) * std::min<uint64_t>(max_pass, uint64_t(1) << std::min<uint64_t>(round, 31));
      if (!timed && target - done < count + uint64_t(ranks_)) count = target - done;
      if (timed && done > 0 &&
          seconds_since(start_) + last_round * double(count) / double(last_count) >= settings.time_limit)
        break;
      // Films travel every few seconds, more rarely when they take long to.
      const bool collect = seconds_since(last_collect) >= std::max(5.0, 4 * collect_cost);
      const Clock::time_point round_start = Clock::now();
      order({next, count, round, collect, 0});
      if (collect) {
        collect_films();
        collect_cost = seconds_since(round_start);
        last_collect = Clock::now();
      }
      const uint64_t rays_before = scene.rays_traced();
      const IndexRange own = rank_share({next, count}, 0, ranks_, round);
      if (!render_own(own)) break;
      rays += scene.rays_traced() - rays_before;
      const double own_seconds = seconds_since(round_start);
      for (int r = 1; r < ranks_; ++r) {
        if (!live_[size_t(r)]) continue;
        const Clock::time_point deadline =
            Clock::now() + std::chrono::duration_cast<Clock::duration>(
                               std::chrono::duration<double>(options_.rank_timeout + 2 * own_seconds));
        Report report;
        if (wait_for(r, kReport, MPI_BYTE, deadline, settings.stop) != int(sizeof report)) {
          if (stopped()) {
            out_.signalled = true;
            break;
          }
          // The others' reports still count: their films hold the round.
          lose(r);
          continue;
        }
        MPI_Recv(&report, sizeof report, MPI_BYTE, r, kReport, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        pending_[size_t(r)].push_back({report.first, report.count});
        rays += report.rays;
      }
      if (out_.signalled || !out_.lost.empty()) break;
      done += count;
      last_round = seconds_since(round_start);
      last_count = count;
      ++round;
      if (progress_) {
        progress_->pixel_samples = done * pixels;
        progress_->rays = rays;
      }
    }
    if (!out_.signalled) {
      order({0, 0, round, 1, 1});
      collect_films();
    }
    run_->finish(out_.result.film);
    RenderStats& stats = out_.result.stats;
    uint64_t spp = 0;
    for (IndexRange r : held_) spp += r.count;
    stats.seconds = seconds_since(start_);
    stats.spp = uint32_t(spp);
    stats.samples = spp * pixels;
    stats.rays = rays;
    stats.dropped = out_.result.film.dropped_samples();
    stats.first_dropped = out_.result.film.first_dropped();
    stats.interrupted = out_.signalled || !out_.lost.empty() || (stopped() && (timed || done < target));
    stats.variance_known = run_->variance_known();
    stats.summary = run_->summary();
    stats.ranks = ranks_;
    const std::string ranges = format_ranges(joined_ranges(held_));
    const std::string whole =
        spp > 0 ? std::to_string(settings.first_sample) + "-" + std::to_string(settings.first_sample + spp - 1) : "";
    if (ranges != whole) stats.ranges = ranges;
    return std::move(out_);
  }

 private:
  void order(const Order& o) {
    for (int r = 1; r < ranks_; ++r)
      if (live_[size_t(r)]) send_bytes(&o, sizeof o, r, kOrder);
  }

  // Adds the films of the live ranks, with the samples they hold.
  void collect_films() {
    const Clock::time_point deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                                          std::chrono::duration<double>(options_.rank_timeout));
    for (int r = 1; r < ranks_; ++r) {
      if (!live_[size_t(r)]) continue;
      const int n = wait_for(r, kFilm, MPI_DOUBLE, deadline, nullptr);
      if (n < 0) {
        lose(r);
        continue;
      }
      std::vector<double> packed(static_cast<size_t>(n));
      MPI_Recv(packed.data(), n, MPI_DOUBLE, r, kFilm, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      out_.result.film.add_packed(packed);
      held_.insert(held_.end(), pending_[size_t(r)].begin(), pending_[size_t(r)].end());
      pending_[size_t(r)].clear();
    }
  }

  void lose(int rank) {
    live_[size_t(rank)] = false;
    out_.lost.push_back(rank);
  }

  // Renders rank 0's share on a thread of its own, so that a signal ends
  // the wait at once (mpirun leaves a second between its SIGTERM and
  // SIGKILL); false if it was stopped.
  bool render_own(IndexRange share) {
    const RenderSettings& settings = job_.settings();
    own_film_->clear();
    const std::shared_ptr<FilmBuffer> film = own_film_;
    auto finished = std::make_shared<std::atomic<int>>(0);  // 1 completed, 2 stopped
    // Not `this`: after a signal the thread outlives the coordinator, so it
    // shares the run and the film (the job stays until the process ends).
    // The progress moves with rank 0's own samples during the round, and
    // takes every rank's at its end.
    std::thread worker([&job = job_, run = run_, progress = progress_, film, finished, share] {
      tbb::task_arena arena(thread_count(job));
      const PassTarget target{*film, progress, thread_count(job), job.settings().stop};
      bool completed = false;
      arena.execute([&] { completed = render_share(*run, share, target); });
      finished->store(completed ? 1 : 2);
    });
    while (finished->load() == 0) {
      if (settings.stop && settings.stop->load()) {
        worker.detach();
        out_.signalled = true;
        return false;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    worker.join();
    if (finished->load() != 1) {
      out_.signalled = true;  // only a stop request ends a pass early
      return false;
    }
    out_.result.film.add(*film);
    held_.push_back(share);
    return true;
  }

  const RenderJob& job_;
  std::shared_ptr<IntegratorRun> run_;
  int ranks_;
  RenderProgress* progress_;
  DistributedOptions options_;
  DistributedRender out_;
  std::vector<std::vector<IndexRange>> pending_;  // per rank: rendered, not yet collected
  std::vector<IndexRange> held_;                  // the samples in out_.result.film
  std::vector<bool> live_;
  // Rank 0's share of a round, added to out_ once whole; shared with the
  // thread that renders it, which may outlive the coordinator.
  std::shared_ptr<FilmBuffer> own_film_ = std::make_shared<FilmBuffer>(fresh_film(job_));
  Clock::time_point start_ = Clock::now();
};

// Each rank other than 0 says which render it loaded (one that could not
// load it says why and ends the job); rank 0 throws on any difference.
void check_ranks_agree(const RenderJob& job, int ranks, double timeout) {
  const std::string mine = description(job);
  const Clock::time_point deadline =
      Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(timeout));
  for (int r = 1; r < ranks; ++r) {
    const int n = wait_for(r, kHello, MPI_CHAR, deadline, nullptr);
    if (n < 0)
      throw std::runtime_error("rank " + std::to_string(r) + " did not load the scene within " +
                               std::to_string(int(timeout)) + " s");
    std::string theirs(size_t(n), '\0');
    MPI_Recv(theirs.data(), n, MPI_CHAR, r, kHello, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    if (theirs != mine)
      throw std::runtime_error("rank " + std::to_string(r) + " loaded another render: '" + theirs +
                               "' where rank 0 has '" + mine + "'");
  }
}

}  // namespace

std::optional<DistributedRender> render_across_ranks(const RenderJob& job, const RankSession& session,
                                                     RenderProgress* progress, const DistributedOptions& options) {
  if (session.rank() != 0) {
    const std::string mine = description(job);
    MPI_Send(mine.data(), int(mine.size()), MPI_CHAR, 0, kHello, MPI_COMM_WORLD);
  } else {
    check_ranks_agree(job, session.size(), options.rank_timeout);
  }
  if (!job.integrator().splits_samples()) {
    if (session.rank() != 0) return std::nullopt;
    return DistributedRender{job.run(progress), {}, false};
  }
  std::shared_ptr<IntegratorRun> run;
  tbb::task_arena arena(thread_count(job));
  arena.execute([&] { run = job.integrator().start(*job.scene(), job.settings().seed); });
  if (session.rank() != 0) {
    serve(job, *run, session.rank(), session.size());
    return std::nullopt;
  }
  return Coordinator(job, std::move(run), session.size(), progress, options).run();
}

std::string distributed_plan(const RenderJob& job, int ranks) {
  const std::string name = job.integrator().plugin_name();
  if (!job.integrator().splits_samples())
    return name + " keeps per-pixel state across iterations: it renders on rank 0 alone, ranks 1 to " +
           std::to_string(ranks - 1) + " stay idle";
  const std::string note = job.integrator().distributed_note();
  return std::to_string(ranks) + " ranks render shares of every round's samples, rank 0 adds their films" +
         (note.empty() ? "" : "; " + note);
}

}  // namespace caustica
