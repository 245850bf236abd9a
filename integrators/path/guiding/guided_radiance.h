#pragma once

#include <algorithm>
#include <array>
#include <optional>

#include "core/render/scatter_density.h"
#include "integrators/path/guiding/guiding_payoff.h"
#include "integrators/path/guiding/spatial_tree.h"
#include "integrators/path/path_radiance.h"

namespace caustica {

// What a guided walk does: sample directions from the learned
// distributions (mixed with the BSDF's, BSDF taken with probability
// bsdf_fraction) and record what the path finds for the next pass.
struct GuidedWalk {
  bool guide = false;
  bool record = false;
  float bsdf_fraction = 0.5f;
  // Whether camera paths' records teach directions too (else light paths
  // alone do, and camera paths only count toward halving regions).
  bool camera_directions = true;
  // GuidingSettings::adjoint_roulette; 0 leaves roulette to path's rule.
  float adjoint_roulette = 0;
  // GuidingSettings::skip_unseen_lights: no light sample at a guided
  // vertex whose guide learnt that its light samples reach no light.
  bool skip_unseen_lights = false;
  // Whether the samples walked are past the training passes: only they
  // meet adjoint-driven roulette, whether or not this render records the
  // pass (a range of a training pass's samples does not), so that a
  // sample is walked alike in every render that takes it.
  bool after_training = false;
};

// Whether a vertex of these lobes is guided: not where any lobe is a delta
// (its directions have no density for a learned distribution to add to).
inline bool guidable(uint32_t lobes) { return (lobes & kDelta) == 0 && (lobes & (kDiffuse | kGlossy)) != 0; }

// The density of the one-sample mixture: the BSDF with probability a, the
// learned distribution (its density over the unit square, guide_square_pdf)
// otherwise. With the balance heuristic, one-sample MIS weighs a sample of
// either by its own share, w_i = c_i p_i / sum_j c_j p_j, so its estimate
// w_i f / (c_i p_i) is f over this density whichever technique drew it.
inline float mixture_pdf(float a, float bsdf_pdf, float guide_square_pdf) {
  return a * bsdf_pdf + (1 - a) * guide_square_pdf * kSquareToSphere;
}

// The path tracer's walk (PathRadiance) with guided directions at guidable
// vertices. Where camera paths teach directions, it records at each of
// them the radiance the rest of the path brings back along its sampled
// direction, over the density it was drawn with: an estimate of the
// radiance's integral over each directional quadrant, which the next pass
// samples in proportion to. Where light paths teach them, it only counts
// its vertices per region, toward halving it. Either way it records the
// radiance each such vertex sent back along the path, which adjoint-driven
// roulette weighs later paths by.
template <bool kMedia>
class GuidedRadiance : public PathRadiance<kMedia>, private ScatterDensity {
 public:
  GuidedRadiance(const Scene& scene, Sampler& sampler, const PathSettings& settings, const Wavelengths* wavelengths,
                 GuidingTree& tree, const GuidedWalk& walk)
      : PathRadiance<kMedia>(scene, sampler, settings, nullptr, wavelengths), tree_(tree), walk_(walk) {}

  WalkAction at_vertex(const WalkVertex& v) {
    region_ = nullptr;
    guide_ = nullptr;
    adjoint_ = false;
    if (walk_.record) arrived_with_ = this->L;
    if ((walk_.guide || walk_.record) && guidable(v.bsdf.lobes())) {
      region_ = &tree_.region_at(v.si.p);
      bucket_ = normal_bucket(dot(v.si.ng, v.wo) < 0 ? -v.si.ng : v.si.ng);
      const DirectionalDistribution& d = region_->guides[bucket_].sampling;
      if (walk_.guide && !d.empty()) guide_ = &d;
    }
    ++cost.vertices;
    if (guide_) ++cost.guided;
    this->density_ = guide_ ? this : nullptr;
    this->gather_emission(v);
    if (v.segments == 1) seen = this->L;
    sampled_lights_ = !(guide_ && walk_.skip_unseen_lights && region_->guides[bucket_].lights_unseen);
    if (!sampled_lights_ || !region_ || !walk_.record || v.last) return this->estimate_direct_light(v, sampled_lights_);
    const Color before = this->L;
    const WalkAction action = this->estimate_direct_light(v);
    region_->guides[bucket_].record_light_sample(!(this->L == before));
    return action;
  }

  // Where no light sample was taken, the emission the next direction meets
  // counts in full (core/transport/random_walk.h).
  bool sampled_lights() const { return sampled_lights_; }

  void escaped(const WalkEscape& e) {
    PathRadiance<kMedia>::escaped(e);
    if (e.segments == 1) seen = this->L;
  }

  std::optional<BsdfSample> sample_scattering(const WalkVertex& v, float u_lobe, Vec2 u) {
    if (region_ && walk_.record && radiance_pending_ < radiance_records_.size())
      radiance_records_[radiance_pending_++] = {&region_->guides[bucket_],
                                                {arrived_with_.r, arrived_with_.g, arrived_with_.b},
                                                {v.beta.r, v.beta.g, v.beta.b}};
    const float survival =
        region_ && walk_.guide && walk_.after_training && walk_.adjoint_roulette > 0 ? adjoint_survival(v) : 1;
    if (survival < 1 && !(this->sampler().next_1d() < survival)) return std::nullopt;
    auto bs = guide_ ? sample_mixture(v, u_lobe, u) : v.bsdf.sample(v.wo, u_lobe, u);
    if (bs && survival < 1) bs->f = bs->f * (1 / survival);
    if (bs && region_ && walk_.record && !walk_.camera_directions) region_->count();
    if (bs && region_ && walk_.record && walk_.camera_directions && pending_ < records_.size()) {
      const Color beta_after = v.beta * (bs->f * (abs_dot(bs->wi, v.si.shading.n) / bs->pdf));
      const Vec2 d = direction_to_square(bs->wi);
      records_[pending_++] = {region_,
                              bucket_,
                              d.x,
                              d.y,
                              bs->pdf,
                              {this->L.r, this->L.g, this->L.b},
                              {beta_after.r, beta_after.g, beta_after.b}};
    }
    return bs;
  }

  // Roulette judges a guided path by what the BSDF alone would have
  // weighed it: a direction the guide prefers has a high density and so a
  // small weight, and a roulette on that weight would end the path in
  // proportion as the guide sent it toward the light, undoing the guide.
  //
  // Where adjoint-driven roulette judged the vertex, path's rule leaves it
  // alone: its throughput does not change there.
  Color roulette_weight(const WalkVertex& v, const BsdfSample& bs) const {
    if (adjoint_) return Color(1);
    const float p = guide_ && bsdf_pdf_ > 0 ? bsdf_pdf_ : bs.pdf;
    return bs.f * (abs_dot(bs.wi, v.si.shading.n) / p);
  }

  // Records what the finished path found beyond each recorded vertex.
  void finish() {
    for (size_t i = 0; i < radiance_pending_; ++i) {
      const RadianceRecord& r = radiance_records_[i];
      if (const auto found = found_beyond(r.before, r.beta)) r.guide->record_radiance(*found);
    }
    for (size_t i = 0; i < pending_; ++i) {
      const Record& r = records_[i];
      r.region->record(r.bucket, {r.x, r.y}, found_beyond(r.found_before, r.beta_after).value_or(0) / double(r.pdf));
    }
  }

  WalkCost cost;
  // The emission the camera's ray met where it first landed: a function of
  // the camera sample alone, the same whether or not the path is guided.
  Color seen;

 private:
  float pdf(Vec3 wi, float bsdf_pdf) const override {
    return mixture_pdf(walk_.bsdf_fraction, bsdf_pdf, guide_->pdf(direction_to_square(wi)));
  }

  // What the finished path gathered after it had gathered `before`, over
  // its weight `beta` then, averaged over the channels that weight is not
  // zero in; nothing where it is zero in all.
  std::optional<double> found_beyond(const float before[3], const float beta[3]) const {
    double sum = 0;
    int channels = 0;
    for (int c = 0; c < 3; ++c)
      if (beta[c] > 0) {
        sum += std::max(0.0f, this->L[c] - before[c]) / double(beta[c]);
        ++channels;
      }
    if (channels == 0) return std::nullopt;
    return sum / channels;
  }

  // Adjoint-driven roulette (Vorba and Křivánek 2016), without its
  // splitting: what the path may still bring back is its weight times the
  // radiance its region was learnt to send, and its pixel's value is
  // taken to be what the path's first such vertex was learnt to send. A
  // path below `adjoint_roulette` of that survives with probability its
  // share over adjoint_roulette. Path's rule (a fixed depth, then a
  // throughput below 0.1) may end a dim path in a bright room, whose rare
  // survivors then carry large weights, and keeps a path in a dark corner
  // going; this rule does the reverse. Any survival probability keeps the
  // estimate unbiased.
  float adjoint_survival(const WalkVertex& v) {
    const float radiance = region_->guides[bucket_].radiance;
    if (!(radiance > 0)) return 1;
    if (!(first_radiance_ > 0)) first_radiance_ = radiance;
    adjoint_ = true;
    const float expected = v.beta.max_component() * radiance / first_radiance_;
    return expected < walk_.adjoint_roulette ? std::max(0.0f, expected / walk_.adjoint_roulette) : 1;
  }

  // u_lobe chooses the technique and, rescaled, the BSDF's lobe.
  std::optional<BsdfSample> sample_mixture(const WalkVertex& v, float u_lobe, Vec2 u) {
    const float a = walk_.bsdf_fraction;
    if (u_lobe < a) {
      auto bs = v.bsdf.sample(v.wo, std::min(u_lobe / a, std::nextafter(1.0f, 0.0f)), u);
      if (bs) {
        bsdf_pdf_ = bs->pdf;
        bs->pdf = pdf(bs->wi, bs->pdf);
      }
      return bs;
    }
    // The guide's density is that at wi mapped back to the square, not
    // the sample's own, so that a sample and a light sample in the same
    // direction meet the same mixture (the map's rounding can move wi
    // across a quadrant's edge).
    const DirectionalDistribution::Sample drawn = guide_->sample(u);
    const Vec3 wi = square_to_direction(drawn.p);
    const auto [f, bsdf_pdf] = v.bsdf.eval_and_pdf(v.wo, wi);
    bsdf_pdf_ = bsdf_pdf;
    const float p = mixture_pdf(walk_.bsdf_fraction, bsdf_pdf, guide_->pdf_near(drawn, direction_to_square(wi)));
    if (f.is_black() || !(p > 0)) return std::nullopt;
    const bool same_side = dot(wi, v.si.ng) * dot(v.wo, v.si.ng) > 0;
    const uint32_t lobes = v.bsdf.lobes() & (same_side ? kReflection : kTransmission);
    // eta only steers roulette (core/transport/random_walk.h), which stays
    // unbiased without it.
    return BsdfSample{wi, f, p, lobes, 1};
  }

  // Plain floats, so that the array below is left uninitialised rather
  // than zeroed for every path, recording or not.
  struct Record {
    GuidingRegion* region;
    int bucket;
    float x, y;  // the direction on the unit square
    float pdf;
    float found_before[3];  // the path's radiance when it left the vertex
    float beta_after[3];    // its weight after the vertex's scattering
  };
  // What the path had gathered when it reached a vertex, and its weight
  // there: all it gathers from the vertex on, over that weight, is a
  // sample of the radiance the vertex sends back.
  struct RadianceRecord {
    DirectionalGuide* guide;
    float before[3];
    float beta[3];
  };
  GuidingTree& tree_;
  const GuidedWalk& walk_;
  GuidingRegion* region_ = nullptr;
  int bucket_ = 0;
  const DirectionalDistribution* guide_ = nullptr;
  float bsdf_pdf_ = 0;  // the BSDF's own density of the last guided vertex's sample
  // Vertices past the 64th record nothing: the paths that reach them teach
  // little, and a fixed array keeps the walk free of allocation.
  std::array<Record, 64> records_;
  size_t pending_ = 0;
  std::array<RadianceRecord, 64> radiance_records_;
  size_t radiance_pending_ = 0;
  Color arrived_with_;          // L as the walk reached the current vertex, where it records
  float first_radiance_ = 0;    // the learnt radiance at the first vertex that had one
  bool adjoint_ = false;        // whether adjoint-driven roulette judged the current vertex
  bool sampled_lights_ = true;  // whether the current vertex took a light sample
};

// A guided walk's radiance (spectral as trace_path), the part of it that
// the camera's ray saw directly (GuidedRadiance::seen), and its cost.
struct GuidedPathSample {
  Color L;
  Color seen;
  WalkCost cost;
};
GuidedPathSample trace_guided_path(const Scene& scene, Ray ray, Sampler& sampler, const PathSettings& settings,
                                   GuidingTree& tree, const GuidedWalk& walk, Wavelengths* wavelengths);

}  // namespace caustica
