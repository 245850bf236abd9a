#pragma once

#include <optional>

#include "core/bsdf/bsdf.h"
#include "core/geometry/interaction.h"

namespace caustica {

// A BSDF placed on a surface point: converts between world and shading
// frames and, once for every material, rejects directions in the tangent
// plane, zero pdfs, and paths whose geometric and shading sides disagree
// (light leaks); in importance mode it applies the adjoint shading-normal
// correction (Veach 1997, section 5.3).
class SurfaceBsdf {
 public:
  // With `wavelengths` (spectral mode) its values are at them.
  SurfaceBsdf(const Bsdf& bsdf, const SurfaceInteraction& si, TransportMode mode,
              const Wavelengths* wavelengths = nullptr)
      : bsdf_(&bsdf), frame_(si.shading), ng_(si.ng), ctx_{mode, si.uv} {
    ctx_.wavelengths = wavelengths;
    // Shapes without a parametrisation leave the tangents zero; the
    // defaults (the shading frame's own axes) stand in for them. Most
    // materials never read them, and skip their transformation.
    if (bsdf.reads_tangents() && squared_length(si.dpdu) > 0 && squared_length(si.dpdv) > 0) {
      ctx_.dpdu = frame_.to_local(si.dpdu);
      ctx_.dpdv = frame_.to_local(si.dpdv);
    }
  }

  Color eval(Vec3 wo_world, Vec3 wi_world) const;
  float pdf(Vec3 wo_world, Vec3 wi_world) const;
  // eval(wo, wi) with pdf(wo, wi), the frame transforms done once.
  struct EvalPdf {
    Color f;
    float pdf;
  };
  EvalPdf eval_and_pdf(Vec3 wo_world, Vec3 wi_world) const;
  // pdf(wo, wi) and pdf(wi, wo), the frame transforms done once.
  struct PdfPair {
    float forward, backward;
  };
  PdfPair pdfs(Vec3 wo_world, Vec3 wi_world) const;
  // eval(wo, wi) with pdfs(wo, wi), the frame transforms done once.
  struct EvalPdfs {
    Color f;
    PdfPair pdf;
  };
  EvalPdfs eval_and_pdfs(Vec3 wo_world, Vec3 wi_world) const;
  // The sample's wi is in world space.
  std::optional<BsdfSample> sample(Vec3 wo_world, float u_lobe, Vec2 u) const;
  Color albedo(Vec3 wo_world) const { return bsdf_->albedo(ctx_, frame_.to_local(wo_world)); }
  uint32_t lobes() const { return bsdf_->lobes(); }
  bool disperses() const { return bsdf_->disperses(); }
  // The path's wavelengths it returns values at (null in RGB mode).
  const Wavelengths* wavelengths() const { return ctx_.wavelengths; }

 private:
  float shading_correction(Vec3 wo_world, Vec3 wi_world) const;
  // A pair of world directions in the shading frame, or none where the BSDF
  // is zero for any material: either in the tangent plane, or the geometric
  // and shading sides disagreeing.
  struct LocalPair {
    Vec3 wo, wi;
  };
  std::optional<LocalPair> local_pair(Vec3 wo_world, Vec3 wi_world) const;

  const Bsdf* bsdf_;
  Frame frame_;
  Vec3 ng_;
  BsdfContext ctx_;
};

}  // namespace caustica
