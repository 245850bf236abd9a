#pragma once

namespace caustica {

class Sensor;

// The angle, in degrees, between the rays through the centres of the two
// pixels either side of the film's centre: what one pixel spans of the
// view, as glare needs it. 0 for a camera whose rays are parallel.
double degrees_per_pixel(const Sensor& sensor);

}  // namespace caustica
