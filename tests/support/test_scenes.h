#pragma once

#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "core/film/film_buffer.h"
#include "core/job/render_job.h"
#include "core/loader/scene_loader.h"

namespace caustica::test {

// A scene from XML text; `name` stands for the file in error messages.
LoadedScene scene_from_xml(const std::string& xml, const std::string& name = "test.xml");

// Renders the scene file's integrator into a fresh film buffer; `stats`,
// if given, receives what the render reports.
FilmBuffer render_scene(const LoadedScene& scene, uint32_t spp, uint64_t seed = 0, int threads = 0,
                        RenderStats* stats = nullptr);

// The message of the SceneError (or other exception) loading `xml` throws,
// or "" if it loads.
std::string load_error(const std::string& xml, const std::string& name = "test.xml");

// scenes/NAME.xml at res x res pixels, rendered by the integrator `spec`
// names ("sppm:photons=10000") instead of the file's.
LoadedScene scene_with_integrator(const std::string& name, const std::string& spec, int res = 24);

// A test name for a scene parameter: "cornell-box-glass" -> "cornell_box_glass".
std::string scene_test_name(const testing::TestParamInfo<const char*>& info);

}  // namespace caustica::test
