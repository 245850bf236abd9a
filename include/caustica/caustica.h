#pragma once

// caustica's public C++ interface, the one header an installed caustica
// offers (find_package(caustica), target caustica::caustica): load a scene,
// render it as `caustica render` does (the same job, so the same numbers
// bit for bit), read the layers of the EXR it would write, write that EXR.
// Everything else in caustica is private to the library.
//
//   namespace cs = caustica::api;
//   const cs::Scene scene = cs::Scene::load("box.xml", {{"res", "64"}});
//   cs::RenderOptions options;
//   options.spp = 16;
//   const cs::Render render = cs::render(scene, options);
//   float red = render.value(10, 20, "R");
//   render.write_exr("box.exr");
//
// Errors are thrown as std::exception (std::invalid_argument,
// std::runtime_error) whose what() is the command line's message, with a
// scene's file and line where the scene is at fault.

#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace caustica::api {

struct Render;
struct RenderOptions;
class Scene;
Render render(const Scene& scene, const RenderOptions& options);

// caustica's version, "MAJOR.MINOR.PATCH".
const char* version();

// A loaded scene: parsed, checked and analysed once, rendered any number
// of times (also at once, from several threads).
class Scene {
 public:
  // `defines` stand for the command line's -D name=value.
  static Scene load(const std::filesystem::path& path, const std::map<std::string, std::string>& defines = {});
  // XML text; `name` stands for its file in messages and resolves the
  // files the scene names.
  static Scene parse(const std::string& xml, const std::filesystem::path& name,
                     const std::map<std::string, std::string>& defines = {});
  const std::string& name() const;

 private:
  struct Loaded;
  explicit Scene(std::shared_ptr<const Loaded> loaded) : loaded_(std::move(loaded)) {}
  std::shared_ptr<const Loaded> loaded_;
  friend Render render(const Scene& scene, const RenderOptions& options);
};

// `caustica render`'s options; zero or empty means what the scene says.
struct RenderOptions {
  std::string integrator;     // NAME or NAME:param=value,...
  uint32_t spp = 0;           // samples per pixel
  uint64_t first_sample = 0;  // the first sample index rendered
  double time_limit = 0;      // seconds, instead of spp
  uint64_t seed = 0;
  int threads = 0;  // 0: every core
  enum class Spectral { AsTheSceneNeeds, On, Off } spectral = Spectral::AsTheSceneNeeds;
  bool raw_sums = false;  // keep the film's raw sums, for exact merges of sample ranges
};

// A render: the layers of the EXR `caustica render` writes, pixel by pixel
// (row-major from the top left, the channels of a pixel together), and its
// metadata (caustica:integrator, caustica:spp, caustica:seconds, ...).
struct Render {
  int width = 0, height = 0;
  std::vector<std::string> channels;  // R, G, B, then albedo.R, ..., variance.R, ...
  std::vector<float> pixels;          // width * height * channels.size()
  std::map<std::string, std::string> metadata;

  // The value of `channel` at pixel (x, y); throws std::out_of_range if the
  // render has no such channel or pixel.
  float value(int x, int y, const std::string& channel) const;
  // Writes the EXR atomically: float, or half where that loses nothing the
  // render needs (never its raw sums).
  void write_exr(const std::filesystem::path& path, bool half_float = false) const;
};

Render render(const Scene& scene, const RenderOptions& options = {});

}  // namespace caustica::api
