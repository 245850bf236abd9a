#pragma once

#include <functional>
#include <map>
#include <string>

#include "core/film/film.h"
#include "core/film/film_buffer.h"
#include "core/image/image_output.h"
#include "core/job/render_job.h"

namespace caustica {

// The layers of a render's EXR: the film's channels, then (for radiance)
// the first-hit layers, the per-pixel variance where it describes the
// estimate, and samples.Y; with `raw_sums`, the films' raw sums (raw.*,
// raw.aov.*), from which renders of disjoint sample ranges merge exactly;
// last, the colour channels the pixel format asks for beside R, G, B (Y
// for luminance, X, Y, Z for xyz, from linear Rec. 709 with its D65 white).
// Rows are made from the films when asked, so the image is never held
// whole unless image() is called.
class RenderLayers {
 public:
  // The first-hit layers come from a film of them (a merge's)...
  RenderLayers(const FilmBuffer& film, const FilmBuffer* aovs, bool variance_known, bool raw_sums,
               PixelFormat format = PixelFormat::Rgb);
  // ... or are evaluated a band of rows at a time as rows are asked for (a
  // render's; none if null); rows() then names them in float_only, as
  // extreme_values() does not evaluate them.
  RenderLayers(const FilmBuffer& film, const FirstHitLayers* layers, bool variance_known, bool raw_sums,
               PixelFormat format = PixelFormat::Rgb);
  // rows() refers to the object itself.
  RenderLayers(const RenderLayers&) = delete;
  RenderLayers& operator=(const RenderLayers&) = delete;
  const ImageRows& rows() const { return rows_; }
  Image image() const;
  // The extreme values among the layers, evaluated first-hit layers aside.
  ExtremeValues extreme_values() const;

 private:
  // The film holding the first-hit layers of rows [y_begin, y_end) and the
  // index in it of pixel (0, y_begin), as a source makes them ready.
  struct AovRows {
    const FilmBuffer* film;
    size_t first_pixel;
  };
  using AovSource = std::function<AovRows(int y_begin, int y_end)>;
  RenderLayers(const FilmBuffer& film, std::vector<std::string> aov_channels, AovSource aovs, bool evaluated,
               bool variance_known, bool raw_sums, PixelFormat format);
  void fill(int y_begin, int y_end, float* out, bool with_evaluated) const;

  struct Layer {
    size_t channels;
    std::function<void(size_t pixel, float* out)> fill;
    bool evaluated = false;  // made by evaluating first-hit layers
  };
  std::vector<Layer> layers_;
  AovSource aov_source_;
  bool aovs_evaluated_ = false;
  mutable AovRows aov_rows_{nullptr, 0};
  ImageRows rows_;
};

Image render_layers(const FilmBuffer& film, const FilmBuffer* aovs, bool variance_known, bool raw_sums);

// The metadata caustica writes beside a render: scene, plan, integrator,
// the sample range, time, counts, seed, what the integrator reported, and
// (with `raw_sums`) the films' channels in order.
std::map<std::string, std::string> render_metadata(const RenderJob& job, const RenderResult& result,
                                                   const std::string& scene_name, bool raw_sums);

// The films' channels in order, for the raw sums of a render (no first-hit
// layers: `aov_channels` empty).
void add_raw_channel_lists(const FilmBuffer& film, const std::vector<std::string>& aov_channels,
                           std::map<std::string, std::string>& metadata);

}  // namespace caustica
