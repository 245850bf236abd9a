// The Python module `caustica`: load a scene, render it as the command line
// does (the same job, so the same numbers bit for bit), and get the layers
// of the EXR the command line would write as numpy arrays, with its
// metadata as a dict; compare renders and develop them for display as
// `caustica compare` and `caustica tonemap` do.
//
//   import caustica
//   scene = caustica.load("scenes/cornell-box.xml", defines={"res": "64"})
//   result = caustica.render(scene, spp=16, seed=1)
//   result.beauty            # H x W x 3 float32
//   result.layers["variance"]
//   result.metadata["caustica:integrator"]
//   caustica.merge([result, caustica.read("other.exr")]).write("both.exr")

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <map>
#include <optional>
#include <string>
#include <thread>

#include "core/errors/scene_error.h"
#include "core/image/image_input.h"
#include "core/image/image_metrics.h"
#include "core/image/image_output.h"
#include "core/image/render_merge.h"
#include "core/job/develop_settings.h"
#include "core/job/merge_parts.h"
#include "core/job/range_merge.h"
#include "core/job/render_job.h"
#include "core/job/render_outputs.h"
#include "core/loader/scene_loader.h"

namespace py = pybind11;

namespace caustica {
namespace {

// A loaded scene and the name its renders record.
struct PyScene {
  LoadedScene loaded;
  std::string name;
};

struct PyResult {
  py::array_t<float> beauty;
  py::dict layers;
  py::dict metadata;
  // What develop(), compare(), merge() and write() read: every layer as the
  // EXR holds them with its metadata, the scene's own tone operator (none
  // for a render read from a file), the camera's degrees per pixel.
  std::shared_ptr<const Image> image;
  std::map<std::string, std::string> metadata_text;
  std::shared_ptr<ToneOperator> scene_tonemap;
  std::optional<double> degrees_per_pixel;
};

// The image's channels grouped as the EXR's layers: "R", "G", "B" make
// the beauty; "variance.R" ... the layer "variance", each H x W x channels.
void split_layers(const Image& image, PyResult& out) {
  std::map<std::string, std::vector<size_t>> groups;
  std::vector<std::string> order;
  for (size_t c = 0; c < image.channels.size(); ++c) {
    const std::string& name = image.channels[c];
    const size_t dot = name.rfind('.');
    const std::string layer = dot == std::string::npos ? "" : name.substr(0, dot);
    if (!groups.count(layer)) order.push_back(layer);
    groups[layer].push_back(c);
  }
  const size_t n = image.channels.size(), pixels = size_t(image.width) * image.height;
  for (const std::string& layer : order) {
    const std::vector<size_t>& channels = groups[layer];
    py::array_t<float> array({size_t(image.height), size_t(image.width), channels.size()});
    float* data = array.mutable_data();
    for (size_t p = 0; p < pixels; ++p)
      for (size_t k = 0; k < channels.size(); ++k) data[p * channels.size() + k] = image.pixels[p * n + channels[k]];
    if (layer.empty())
      out.beauty = array;
    else
      out.layers[py::str(layer)] = array;
  }
}

PyResult make_result(Image image, std::map<std::string, std::string> metadata,
                     std::shared_ptr<ToneOperator> scene_tonemap) {
  PyResult out;
  split_layers(image, out);
  for (const auto& [key, value] : metadata) out.metadata[py::str(key)] = value;
  out.degrees_per_pixel = recorded_degrees_per_pixel(metadata);
  out.image = std::make_shared<const Image>(std::move(image));
  out.metadata_text = std::move(metadata);
  out.scene_tonemap = std::move(scene_tonemap);
  return out;
}

PyScene load_file(const std::filesystem::path& path, const Defines& defines) {
  return {load_scene(path, defines), path.string()};
}

PyScene load_text(const std::string& xml, const Defines& defines, const std::string& name) {
  return {load_scene_string(xml, name, defines), name};
}

PyResult render_scene(const PyScene& scene, const std::string& integrator, uint32_t spp, uint64_t first_sample,
                      double time, uint64_t seed, int threads, const std::string& spectral, bool raw_sums,
                      const std::string& light_selection) {
  RenderSettings settings;
  settings.integrator = integrator;
  settings.spp = spp;
  settings.first_sample = first_sample;
  settings.time_limit = time;
  settings.seed = seed;
  settings.threads = threads;
  if (spectral == "on")
    settings.transport = RenderSettings::Transport::Spectral;
  else if (spectral == "off")
    settings.transport = RenderSettings::Transport::Rgb;
  else if (spectral != "auto")
    throw py::value_error("spectral must be 'on', 'off' or 'auto', not '" + spectral + "'");
  if (light_selection == "tree")
    settings.light_selection = RenderSettings::LightSelection::Tree;
  else if (light_selection == "power")
    settings.light_selection = RenderSettings::LightSelection::Power;
  else if (light_selection != "auto")
    throw py::value_error("light_selection must be 'tree', 'power' or 'auto', not '" + light_selection + "'");
  std::atomic<bool> stop{false};
  settings.stop = &stop;
  Image image;
  std::map<std::string, std::string> metadata;
  std::exception_ptr failure;
  std::optional<py::error_already_set> interrupt;
  {
    // The render runs beside this thread, which keeps looking for Python's
    // signals: Ctrl-C stops the render at its next pass and raises
    // KeyboardInterrupt here once it has.
    py::gil_scoped_release released;
    std::atomic<bool> done{false};
    std::thread worker([&] {
      try {
        const RenderJob job(scene.loaded, settings);
        const RenderResult result = job.run();
        const std::optional<FirstHitLayers> first_hit = job.first_hit_layers(result);
        image =
            RenderLayers(result.film, first_hit ? &*first_hit : nullptr, result.stats.variance_known, raw_sums).image();
        metadata = render_metadata(job, result, scene.name, raw_sums);
      } catch (...) {
        failure = std::current_exception();
      }
      done = true;
    });
    while (!done) {
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
      py::gil_scoped_acquire held;
      if (!interrupt && PyErr_CheckSignals() != 0) {
        interrupt.emplace();
        stop = true;
      }
    }
    worker.join();
  }
  if (interrupt) throw *interrupt;
  if (failure) std::rethrow_exception(failure);
  return make_result(std::move(image), std::move(metadata), scene.loaded.tone_operator);
}

PyResult read_result(const std::filesystem::path& path) {
  RenderFile file = read_render(path.string());
  return make_result(std::move(file.image), std::move(file.metadata), nullptr);
}

void write_result(const PyResult& result, const std::filesystem::path& path, const std::string& exr_format) {
  if (path.extension() != ".exr") throw py::value_error("output must end in .exr: " + path.string());
  if (exr_format != "half" && exr_format != "float")
    throw py::value_error("exr_format must be 'half' or 'float', not '" + exr_format + "'");
  py::gil_scoped_release released;
  const bool half = exr_format == "half" && half_float_suits({path.string(), *result.image, result.metadata_text});
  write_exr(path.string(), *result.image, result.metadata_text, half);
}

// An EXR path as Python gives one (str or os.PathLike); anything else is
// refused naming what `what` takes.
std::filesystem::path path_of(const py::object& source, const char* what) {
  if (!py::isinstance<py::str>(source) && !py::hasattr(source, "__fspath__"))
    throw py::type_error(std::string(what) + " takes results or EXR paths, not " +
                         std::string(py::str(source.get_type().attr("__name__"))));
  return source.cast<std::filesystem::path>();
}

// Parts as `caustica merge` merges them: results, or EXR paths; a result
// is named in messages by its place in the list.
PyResult merge(const std::vector<py::object>& sources) {
  std::vector<RenderFile> parts;
  for (size_t i = 0; i < sources.size(); ++i) {
    if (py::isinstance<PyResult>(sources[i])) {
      const PyResult& result = sources[i].cast<const PyResult&>();
      parts.push_back({"result " + std::to_string(i), *result.image, result.metadata_text});
    } else {
      parts.push_back(read_render(path_of(sources[i], "merge").string()));
    }
  }
  if (parts.empty()) throw py::value_error("merge takes at least one render");
  RenderFile merged;
  {
    py::gil_scoped_release released;
    merged = merge_parts(std::move(parts));
  }
  return make_result(std::move(merged.image), std::move(merged.metadata), nullptr);
}

// A render's layers: a result's, or an EXR's read from its path.
std::shared_ptr<const Image> image_of(const py::object& source) {
  if (py::isinstance<PyResult>(source)) return source.cast<const PyResult&>().image;
  const std::filesystem::path path = path_of(source, "compare");
  require_linear_image(path);
  return std::make_shared<const Image>(read_image(path));
}

py::dict compare(const py::object& image, const py::object& reference, double epsilon) {
  const ErrorMetrics m = compare_images(*image_of(image), *image_of(reference), epsilon);
  py::dict out;
  out["mse"] = m.mse;
  out["mse_corrected"] = m.mse_corrected;
  out["rel_mse"] = m.rel_mse;
  out["rel_mse_corrected"] = m.rel_mse_corrected;
  out["mae"] = m.mae;
  // Each image's estimate of its own error, from its variance layers; NaN
  // where it has none.
  const auto known = [](const EstimatedError& e, double v) { return e.known ? v : std::nan(""); };
  out["reference_estimated_mse"] = known(m.reference, m.reference.mse);
  out["reference_estimated_rel_mse"] = known(m.reference, m.reference.rel_mse);
  out["estimated_mse"] = known(m.image, m.image.mse);
  out["estimated_rel_mse"] = known(m.image, m.image.rel_mse);
  return out;
}

// The display-encoded H x W x 3 image `caustica tonemap` would write to a
// 16-bit PNG, before quantisation: from a result (its scene's tone
// operator and camera by default) or an H x W x 3 scene-linear array.
py::array_t<float> develop(const py::object& source, const DevelopSettings& settings) {
  Image image;
  std::shared_ptr<ToneOperator> scene_default;
  std::optional<double> pixel_angle;
  if (py::isinstance<PyResult>(source)) {
    const PyResult& result = source.cast<const PyResult&>();
    image = *result.image;
    scene_default = result.scene_tonemap;
    pixel_angle = result.degrees_per_pixel;
  } else {
    const auto array = source.cast<py::array_t<float, py::array::c_style | py::array::forcecast>>();
    if (array.ndim() != 3 || array.shape(2) != 3)
      throw py::value_error("develop takes a result or an H x W x 3 array of scene-linear RGB");
    image = {int(array.shape(1)),
             int(array.shape(0)),
             {"R", "G", "B"},
             std::vector<float>(array.data(), array.data() + array.size())};
  }
  // An exposure given here replaces the operator's own, which the scene
  // shares with every result: it is put back once the image is developed.
  const float scene_exposure = scene_default ? scene_default->exposure() : 0;
  struct RestoreExposure {
    ToneOperator* op;
    float ev;
    ~RestoreExposure() {
      if (op) op->set_exposure(ev);
    }
  } restore{scene_default.get(), scene_exposure};
  const Developer developer = make_developer(settings, scene_default, std::nullopt, pixel_angle);
  const size_t width = size_t(image.width), height = size_t(image.height);
  std::vector<float> display;
  {
    py::gil_scoped_release released;
    display = developer.develop(std::move(image));
  }
  py::array_t<float> out({height, width, size_t(3)});
  std::copy(display.begin(), display.end(), out.mutable_data());
  return out;
}

}  // namespace
}  // namespace caustica

PYBIND11_MODULE(caustica, m) {
  using namespace caustica;
  m.doc() = "caustica: a physically based Monte Carlo renderer";
  // A scene's errors carry its file and line in their message, and as the
  // attributes `file` and `line` (0 where the problem has no line).
  static py::exception<SceneError> scene_error(m, "SceneError", PyExc_ValueError);
  py::register_exception_translator([](std::exception_ptr failure) {
    try {
      if (failure) std::rethrow_exception(failure);
    } catch (const SceneError& e) {
      py::object error = static_cast<py::object&>(scene_error)(e.what());
      error.attr("file") = e.where().file;
      error.attr("line") = e.where().line;
      PyErr_SetObject(scene_error.ptr(), error.ptr());
    }
  });
  py::class_<PyScene>(m, "Scene").def_readonly("name", &PyScene::name);
  py::class_<PyResult>(m, "Result")
      .def_readonly("beauty", &PyResult::beauty)
      .def_readonly("layers", &PyResult::layers)
      .def_readonly("metadata", &PyResult::metadata)
      .def("write", &write_result, py::arg("path"), py::arg("exr_format") = "float",
           "Writes the render's EXR (every layer, the metadata) as `caustica render` does, atomically; "
           "in float where half would lose raw sums or values beyond 65504.");
  m.def("load", &load_file, py::arg("path"), py::arg("defines") = Defines{},
        "Loads a scene file; defines are the command line's -D name=value.");
  m.def("load_string", &load_text, py::arg("xml"), py::arg("defines") = Defines{}, py::arg("name") = "string.xml",
        "Loads a scene from XML text; name stands for the file in messages.");
  m.def("render", &render_scene, py::arg("scene"), py::kw_only(), py::arg("integrator") = "", py::arg("spp") = 0,
        py::arg("first_sample") = 0, py::arg("time") = 0.0, py::arg("seed") = 0, py::arg("threads") = 0,
        py::arg("spectral") = "auto", py::arg("raw_sums") = false, py::arg("light_selection") = "auto",
        "Renders as `caustica render` does; returns beauty, layers and metadata.");
  m.def("read", &read_result, py::arg("path"), "Reads a render's EXR as a result.");
  m.def("merge", &merge, py::arg("parts"),
        "Merges renders (results or EXR paths) as `caustica merge` does: disjoint sample ranges of one seed "
        "with raw sums exactly, independent renders by sample count.");
  m.def("compare", &compare, py::arg("image"), py::arg("reference"), py::arg("epsilon") = kRelMseEpsilon,
        "Errors of a render (a result or an EXR path) against a reference, as `caustica compare` reports them.");
  m.def(
      "develop",
      [](const py::object& source, const std::string& tonemap, std::optional<float> exposure,
         std::optional<std::string> glare, std::optional<double> degrees_per_pixel, const std::string& display,
         const std::string& view, const std::string& look, const std::string& ocio_config) {
        return develop(source, {tonemap, display, view, look, ocio_config, exposure, glare, degrees_per_pixel});
      },
      py::arg("image"), py::kw_only(), py::arg("tonemap") = "", py::arg("exposure") = py::none(),
      py::arg("glare") = py::none(), py::arg("degrees_per_pixel") = py::none(), py::arg("display") = "",
      py::arg("view") = "", py::arg("look") = "", py::arg("ocio_config") = "",
      "Develops a result or a scene-linear H x W x 3 array for display, as `caustica tonemap` does.");
}
