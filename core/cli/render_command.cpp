#include "core/cli/render_command.h"

#include <cstdio>
#include <filesystem>
#include <limits>
#include <optional>
#include <sstream>
#include <thread>

#include "core/camera/pixel_angle.h"
#include "core/cli/interrupt.h"
#include "core/cli/number_checks.h"
#include "core/cli/progress_display.h"
#include "core/errors/interrupted.h"
#include "core/image/image_output.h"
#include "core/job/distributed_render.h"
#include "core/job/render_job.h"
#include "core/job/render_outputs.h"
#include "core/job/replay_command.h"

namespace caustica {

void RenderCommand::add_to(CLI::App& app) {
  command_ = app.add_subcommand("render", "render a scene to OUT.exr (linear) and OUT.png (display)");
  command_->add_option("scene", scene_, "Mitsuba 3 scene file")->required()->check(CLI::ExistingFile);
  command_->add_option("-o,--output", output_,
                       "linear output: .exr, or .hdr (Radiance RGBE) or .pfm with the beauty only (default: "
                       "SCENE_NAME and the film's file_format); the PNG goes beside it");
  auto* spp = command_->add_option("--spp", spp_, "samples per pixel (default: the scene's sampler)")
                  ->check(CLI::Range(1u, 1u << 31));
  command_->add_option("--time", time_, "render for this many seconds instead")
      ->excludes(spp)
      ->check(finite_positive());
  command_
      ->add_option("--first-sample", first_sample_,
                   "first sample index: render indices N .. N+spp-1, to merge with renders of other ranges")
      ->check(whole_number_up_to(kMaxFirstSample, "2^62"));
  command_->add_flag("--raw-sums", raw_sums_,
                     "store the film's raw sums (float EXR), so that `caustica merge` of renders of disjoint "
                     "--first-sample ranges gives exactly the image of one render");
  command_->add_option("--integrator", integrator_, "replace the scene's integrator: NAME or NAME:param=value,...");
  command_->add_option("-D", defines_, "define a scene parameter: -D name=value")->allow_extra_args(false);
  command_->add_option("--threads", threads_, "worker threads (default: all cores)")->check(CLI::Range(0, kMaxThreads));
  command_->add_option("--seed", seed_, "random seed")
      ->check(whole_number_up_to(std::numeric_limits<uint64_t>::max(), "2^64 - 1"));
  command_->add_option("--exr-format", exr_format_, "half or float (default: the film's component_format)")
      ->check(CLI::IsMember({"half", "float"}));
  command_
      ->add_option("--spectral", spectral_,
                   "on: paths carry wavelengths; off: RGB; auto: as the scene needs (default: auto)")
      ->check(CLI::IsMember({"on", "off", "auto"}));
  command_
      ->add_option("--light-selection", light_selection_,
                   "how a lit point chooses its light: tree (near and bright lights first), power, or auto: the "
                   "tree where it holds two emitters or more (default: auto)")
      ->check(CLI::IsMember({"tree", "power", "auto"}));
  command_->add_option("--debug-pixel", debug_pixel_, "replay one sample of pixel X,Y and print it");
  command_->add_option("--debug-sample", debug_sample_, "the sample index --debug-pixel replays")
      ->check(whole_number_up_to(kMaxFirstSample, "2^62"));
  command_->add_flag("-q,--quiet", quiet_, "print nothing but errors");
  command_
      ->add_option("--rank-timeout", rank_timeout_,
                   "under mpirun: seconds a rank may stay silent (beyond what rank 0's own share of a round "
                   "took) before rank 0 writes what the others rendered and ends the job")
      ->check(finite_positive());
  develop_.add_to(*command_);
}

namespace {

// The linear output's file: -o, else the scene's name with the extension of
// the film's file_format.
std::filesystem::path linear_output(const std::string& output, const std::string& scene, const Film& film) {
  if (!output.empty()) {
    const std::filesystem::path path = output;
    const std::string ext = path.extension().string();
    if (ext != ".exr" && ext != ".hdr" && ext != ".pfm")
      throw std::invalid_argument("output must end in .exr, .hdr or .pfm: " + output);
    return path;
  }
  const FileFormat format = film.output().file;
  const char* ext = format == FileFormat::Rgbe ? ".hdr" : format == FileFormat::Pfm ? ".pfm" : ".exr";
  return std::filesystem::path(scene).stem().string() + ext;
}

}  // namespace

int RenderCommand::replay(const RenderJob& job) const {
  const Film& film = *job.scene()->sensor().film();
  int x = -1, y = -1;
  char comma = 0;
  std::istringstream in(debug_pixel_);
  if (!(in >> x >> comma >> y) || comma != ',' || x < 0 || y < 0 || x >= film.width() || y >= film.height())
    throw std::invalid_argument("--debug-pixel expects X,Y inside the film, got '" + debug_pixel_ + "'");
  const ReplayedSample sample = job.replay({x, y}, debug_sample_);
  const auto names = job.integrator().channels();
  for (size_t c = 0; c < sample.values.size(); ++c) std::printf("%s = %.9g\n", names[c].c_str(), sample.values[c]);
  for (const Splat& s : sample.splats.splats())
    std::printf("splat at (%.3f, %.3f) to %s: %.9g %.9g %.9g\n", s.raster.x, s.raster.y, names[s.channel].c_str(),
                s.value.r, s.value.g, s.value.b);
  if (sample.splats.dropped() > 0)
    std::printf("%llu non-finite splats dropped\n", (unsigned long long)sample.splats.dropped());
  return 0;
}

int RenderCommand::run() const {
  // Installed first, so an interrupt while the scene loads still ends in an
  // image (of the first pass) rather than in nothing.
  install_interrupt_handler();
  if (!started_by_mpirun()) return render(nullptr);
  const RankSession session;
  try {
    return render(&session);
  } catch (const Interrupted& e) {
    std::fprintf(stderr, "caustica: %s\n", e.what());
    std::fflush(stderr);
    std::_Exit(130);
  } catch (const std::exception& e) {
    // The other ranks wait for this one: the job ends with it.
    std::fprintf(stderr, "caustica: rank %d: error: %s\n", session.rank(), e.what());
    std::fflush(stderr);
    session.abort(1);
  }
}

int RenderCommand::render(const RankSession* session) const {
  const bool rank0 = !session || session->rank() == 0;
  RenderSettings settings;
  settings.integrator = integrator_;
  settings.spp = spp_;
  settings.first_sample = first_sample_;
  settings.time_limit = time_;
  settings.seed = seed_;
  settings.transport = spectral_ == "on"    ? RenderSettings::Transport::Spectral
                       : spectral_ == "off" ? RenderSettings::Transport::Rgb
                                            : RenderSettings::Transport::AsTheSceneNeeds;
  settings.light_selection = light_selection_ == "tree"    ? RenderSettings::LightSelection::Tree
                             : light_selection_ == "power" ? RenderSettings::LightSelection::Power
                                                           : RenderSettings::LightSelection::AsTheSceneNeeds;
  // The ranks on one machine share its cores.
  settings.threads = threads_ > 0 || !session
                         ? threads_
                         : std::max(1, int(std::thread::hardware_concurrency()) / session->local_size());
  settings.stop = &interrupt_requested();
  const RenderJob job = load_render_job(scene_, parse_defines(defines_), settings);
  if (rank0)
    for (const std::string& warning : job.scene().warnings)
      std::fprintf(stderr, "caustica: warning: %s\n", warning.c_str());
  if (!debug_pixel_.empty()) return rank0 ? replay(job) : 0;

  const Film& film = *job.scene()->sensor().film();
  const std::filesystem::path exr = linear_output(output_, scene_, film);
  const bool plain = exr.extension() != ".exr";
  if (plain && raw_sums_) throw std::invalid_argument("--raw-sums needs an .exr output, not " + exr.string());
  std::filesystem::path png = exr;
  const auto& ldr = film.output().ldr;
  png.replace_extension(ldr && ldr->jpeg ? ".jpg" : ".png");
  // Everything that can fail on bad options fails before the render.
  const Developer developer =
      develop_.make(job.scene().tone_operator, film.output().ldr, degrees_per_pixel(job.scene()->sensor()));

  std::string plan = job.plan();
  if (session) plan += (plan.empty() ? "" : "\n") + distributed_plan(job, session->size());
  if (!quiet_ && rank0 && !plan.empty()) {
    std::printf("%s\n", plan.c_str());
    // The line that says loading is over, for whoever reads a pipe.
    std::fflush(stdout);
  }
  RenderProgress progress;
  std::optional<RenderResult> result;
  std::optional<DistributedRender> distributed;
  {
    std::optional<ProgressDisplay> display;
    if (!quiet_ && rank0) display.emplace(progress, time_);
    if (!session)
      result = job.run(&progress);
    else if ((distributed = render_across_ranks(job, *session, &progress, {rank_timeout_})))
      result = std::move(distributed->result);
  }
  if (!rank0) return 0;
  if (distributed && result->stats.spp == 0) {
    std::fprintf(stderr, "caustica: interrupted before any samples were collected\n");
    std::fflush(stderr);
    // Rank 0's own share may still be rendering with this job: no unwinding.
    std::_Exit(130);
  }
  const RenderStats& stats = result->stats;

  const std::optional<FirstHitLayers> first_hit = job.first_hit_layers(*result);
  const uint64_t layer_rays_before = job.scene()->layer_rays_traced();
  const RenderLayers layers(result->film, first_hit ? &*first_hit : nullptr, stats.variance_known, raw_sums_,
                            film.output().pixels);
  std::map<std::string, std::string> metadata = render_metadata(job, *result, scene_, raw_sums_);
  metadata["caustica:develop"] = developer.describe();
  bool half = !raw_sums_ && !plain && (exr_format_.empty() ? film.half_float() : exr_format_ == "half");
  const ExtremeValues extreme = layers.extreme_values();
  if (half && extreme.beyond_half > 0) {
    half = false;
    std::fprintf(stderr, "caustica: note: %zu values exceed 65504, the largest half float: %s is written in float\n",
                 extreme.beyond_half, exr.c_str());
  }
  if (extreme.at_float_limit > 0)
    std::fprintf(stderr,
                 "caustica: warning: %zu variance values exceed the float range and are clamped to its largest\n",
                 extreme.at_float_limit);
  if (!plain)
    write_exr(exr, layers.rows(), metadata, half);
  else if (exr.extension() == ".pfm" && film.output().pixels == PixelFormat::Luminance)
    write_plain_float(exr, layers.image(), {"Y"});
  else
    write_plain_float(exr, layers.image(), {"R", "G", "B"});
  // The picture needs only the beauty: it is resolved again rather than
  // taken from a whole image of every layer.
  const FilmBuffer& beauty = result->film;
  bool glare_spread = false;
  write_png(
      png, beauty.width(), beauty.height(),
      developer.develop(Image{beauty.width(), beauty.height(), beauty.channels(), beauty.resolve()}, &glare_spread),
      develop_.png_bits());
  if (!quiet_ && developer.glare().mode == GlareMode::Clipped && !glare_spread)
    std::printf("glare: skipped, no pixel exceeds the display's range\n");
  const uint64_t layer_rays = job.scene()->layer_rays_traced() - layer_rays_before;

  if (!quiet_) {
    std::printf(
        "%s: %s, %dx%d, %u spp in %.2f s, %.3g M samples/s, %.3g M rays/s (the integrator's rays; the first-hit "
        "layers' %.3g M rays apart), %llu non-finite samples dropped%s%s -> %s, %s\n",
        scene_.c_str(), job.integrator().describe().c_str(), film.width(), film.height(), stats.spp, stats.seconds,
        stats.samples / stats.seconds * 1e-6, stats.rays / stats.seconds * 1e-6, double(layer_rays) * 1e-6,
        static_cast<unsigned long long>(stats.dropped), stats.interrupted ? ", interrupted" : "",
        stats.ranks > 1 ? (", " + std::to_string(stats.ranks) + " ranks").c_str() : "", exr.c_str(), png.c_str());
  }
  if (stats.dropped > 0)
    std::fprintf(stderr, "caustica: warning: %llu non-finite samples were dropped; replay the first with:\n  %s\n",
                 static_cast<unsigned long long>(stats.dropped),
                 replay_command(scene_, defines_, settings, stats.first_dropped).c_str());
  if (distributed) end_distributed(*distributed, stats, *session, exr);
  return 0;
}

void RenderCommand::end_distributed(const DistributedRender& render, const RenderStats& stats,
                                    const RankSession& session, const std::filesystem::path& exr) const {
  const std::string held =
      std::to_string(stats.spp) + " samples per pixel" + (stats.ranges.empty() ? "" : " (caustica:ranges lists which)");
  if (render.signalled) {
    std::fprintf(stderr,
                 "caustica: stopped by a signal while the ranks rendered (mpirun ends every rank on Ctrl-C, and when "
                 "a rank fails, naming it above): %s holds the %s collected before\n",
                 exr.c_str(), held.c_str());
    std::fflush(stdout);
    std::fflush(stderr);
    // Rank 0's own share may still be rendering on another thread.
    std::_Exit(130);
  }
  if (render.lost.empty()) return;
  std::string lost;
  for (int rank : render.lost) lost += (lost.empty() ? "" : ", ") + std::to_string(rank);
  std::fprintf(stderr,
               "caustica: error: lost rank %s (no answer within --rank-timeout %g s): %s holds the %s that the "
               "ranks still answering rendered; with --raw-sums, render more samples with --first-sample and merge\n",
               lost.c_str(), rank_timeout_, exr.c_str(), held.c_str());
  std::fflush(stdout);
  std::fflush(stderr);
  // MPI cannot finalise with a rank gone.
  session.abort(4);
}

}  // namespace caustica
