#include "core/render/camera_sample.h"

#include "core/scene/scene.h"

namespace caustica {

CameraSample sample_camera_ray(const Scene& scene, Sampler& sampler, Vec2i pixel, uint64_t index, uint64_t seed,
                               std::optional<float> time) {
  sampler.start_sample(SampleKey::camera(pixel), index, seed);
  const Sensor& sensor = scene.sensor();
  const FilterSample fs = sensor.film()->filter().sample(sampler.next_2d());
  const Vec2 raster{float(pixel.x) + 0.5f + fs.offset.x, float(pixel.y) + 0.5f + fs.offset.y};
  const Vec2 u_lens = sensor.has_lens() ? sampler.next_2d() : Vec2(0.5f, 0.5f);
  return {sensor.generate_ray(raster, u_lens, time ? *time : sample_shutter_time(scene, sampler)), fs.weight};
}

float sample_shutter_time(const Scene& scene, Sampler& sampler) {
  return scene.features().motion ? sampler.next_1d() : 0.0f;
}

}  // namespace caustica
