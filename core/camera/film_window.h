#pragma once

#include "core/film/film.h"
#include "core/math/vec.h"

namespace caustica {

// The part of the film a render covers (its crop window) within the whole
// film, as every sensor maps it: raster positions count from the window's
// corner, film positions are fractions of the whole film's width and height.
struct FilmWindow {
  explicit FilmWindow(const Film& film)
      : size{float(film.full_size().x), float(film.full_size().y)},
        crop{float(film.crop_offset().x), float(film.crop_offset().y)},
        window{float(film.width()), float(film.height())} {}

  Vec2 to_film(Vec2 raster) const { return {(raster.x + crop.x) / size.x, (raster.y + crop.y) / size.y}; }
  Vec2 to_raster(Vec2 film) const { return {film.x * size.x - crop.x, film.y * size.y - crop.y}; }
  bool contains(Vec2 raster) const {
    return raster.x >= 0 && raster.x < window.x && raster.y >= 0 && raster.y < window.y;
  }
  // The window's share of the film's area: a sensor's importance integrates
  // to one over what is rendered.
  float fraction() const { return (window.x / size.x) * (window.y / size.y); }

  Vec2 size, crop, window;
};

}  // namespace caustica
