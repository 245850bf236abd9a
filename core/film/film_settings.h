#pragma once

#include <memory>
#include <vector>

#include "core/film/film.h"
#include "core/registry/param_spec.h"

namespace caustica {

class Properties;

// What hdrfilm and ldrfilm read alike: the film's size, its crop window and
// reconstruction filter (checked, with a line for each parameter that
// changes nothing), and the pixel format.
FilmGeometry read_film_geometry(const Properties& props);
// Sets pixels and alpha from pixel_format, one of `accepted`.
void read_pixel_format(const Properties& props, FilmOutput& out, const std::vector<std::string>& accepted);
// The parameters read_film_geometry reads.
std::vector<ParamSpec> film_geometry_params();

}  // namespace caustica
