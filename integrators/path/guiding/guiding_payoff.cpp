#include "integrators/path/guiding/guiding_payoff.h"

#include <algorithm>
#include <cmath>

#include "core/image/image_metrics.h"

namespace caustica {

namespace {
namespace CAUSTICA_UNITY_ID {

constexpr double kMaxTracked = 65536;

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

GuidingPayoff::GuidingPayoff(int width, int height)
    : stride_(std::max(1, int(std::ceil(std::sqrt(double(width) * double(height) / kMaxTracked))))),
      columns_((width + stride_ - 1) / stride_),
      pixels_(size_t(columns_) * size_t((height + stride_ - 1) / stride_), Pixel{}) {}

GuidingPayoff::Pixel* GuidingPayoff::tracked(Vec2i p) {
  if (p.x % stride_ != 0 || p.y % stride_ != 0) return nullptr;
  return &pixels_[size_t(p.y / stride_) * size_t(columns_) + size_t(p.x / stride_)];
}

void GuidingPayoff::begin_pass(uint32_t pass) {
  if (pass_ == 0 && pass > 0) pass0_cost_ = cost_per_sample();
  for (Pixel& px : pixels_)
    for (int c = 0; c < 3; ++c) {
      if (pass == 0) px.first[c] = px.earlier[c] = 0;
      if (pass_ > 0 && pass > pass_) px.earlier[c] += px.sum[c];
      px.sum[c] = px.squares[c] = 0;
    }
  for (Pixel& px : pixels_) px.samples = px.vertices = px.guided = 0;
  pass_ = pass;
}

void GuidingPayoff::add(Vec2i pixel, const Color& L, const WalkCost& cost) {
  Pixel* px = tracked(pixel);
  if (!px) return;
  ++px->samples;
  px->vertices += cost.vertices;
  px->guided += cost.guided;
  for (int c = 0; c < 3; ++c) {
    if (pass_ == 0) px->first[c] = L[c];
    px->sum[c] += L[c];
    px->squares[c] += double(L[c]) * L[c];
  }
}

GuidingPayoff::Verdict GuidingPayoff::judge() const {
  const double n = std::ldexp(1.0, int(pass_));  // samples per pixel of pass k
  const double after_first = 2 * n - 2;          // of passes 1 .. k
  double guided = 0, unguided = 0;
  for (const Pixel& px : pixels_)
    for (int c = 0; c < 3; ++c) {
      const double variance = std::max(0.0, (px.squares[c] - px.sum[c] * px.sum[c] / n) / (n - 1));
      const double mean = (px.earlier[c] + px.sum[c]) / after_first;
      const double weight = 1 / (mean * mean + kRelMseEpsilon);
      guided += variance * weight;
      const double d = px.first[c] - mean;
      unguided += (d * d - variance / after_first) * weight;
    }
  const double values = double(pixels_.size()) * 3;
  return {unguided / values, pass0_cost_, guided / values, cost_per_sample()};
}

double GuidingPayoff::cost_per_sample() const {
  uint64_t samples = 0, vertices = 0, guided = 0;
  for (const Pixel& px : pixels_) {
    samples += px.samples;
    vertices += px.vertices;
    guided += px.guided;
  }
  if (samples == 0) return 0;
  return (double(vertices) + kGuidedVertexExtra * double(guided)) / double(samples);
}

}  // namespace caustica
