#include "core/loader/scene_loader.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <sstream>

#include "core/bsdf/bsdf.h"
#include "core/camera/clip_check.h"
#include "core/camera/moving_sensor.h"
#include "core/errors/interrupted.h"
#include "core/lights/emitter.h"
#include "core/lights/moving_emitter.h"
#include "core/loader/spectrum_value.h"
#include "core/loader/transform_parser.h"
#include "core/loader/xml_reader.h"
#include "core/math/animated_transform.h"
#include "core/math/shutter_keys.h"
#include "core/media/medium.h"
#include "core/registry/file_resolver.h"
#include "core/registry/ignored_params.h"
#include "core/registry/properties.h"
#include "core/registry/property_value.h"
#include "core/scene/scene_extent.h"
#include "core/shapes/moving_shape.h"

namespace caustica {

namespace {
namespace CAUSTICA_UNITY_ID {

const std::set<std::string> kObjectTags = {"integrator", "sensor",  "film",    "sampler", "rfilter", "shape", "bsdf",
                                           "emitter",    "texture", "tonemap", "medium",  "phase",   "volume"};
const std::map<std::string, ValueKind> kValueTags = {{"float", ValueKind::Float},     {"integer", ValueKind::Integer},
                                                     {"boolean", ValueKind::Boolean}, {"string", ValueKind::String},
                                                     {"rgb", ValueKind::Rgb},         {"point", ValueKind::Point},
                                                     {"vector", ValueKind::Vector}};

const std::string& required_attribute(const XmlNode& node, const char* name) {
  const std::string* v = node.attribute(name);
  if (!v) throw SceneError(node.where, "<" + node.tag + "> needs a '" + name + "' attribute");
  return *v;
}

PropertyValue parse_value_element(const XmlNode& node, ValueKind kind) {
  if ((kind == ValueKind::Point || kind == ValueKind::Vector) && !node.attribute("value")) {
    node.check_attributes({"name", "x", "y", "z"});
    const auto coord = [&](const char* a) {
      const std::string* v = node.attribute(a);
      return v ? std::get<double>(parse_value_text(ValueKind::Float, *v, node.where).value) : 0.0;
    };
    return {kind, Vec3d(coord("x"), coord("y"), coord("z")), node.where};
  }
  node.check_attributes({"name", "value"});
  return parse_value_text(kind, required_attribute(node, "value"), node.where);
}

// Instantiates plugins from nodes, each object once, resolving <ref> by id.
class Instantiator {
 public:
  // An <animation>'s keys, in the order written, and where it was written.
  struct Animation {
    std::vector<std::pair<double, Transform>> keys;
    SourceLocation where;

    std::vector<double> times() const {
      std::vector<double> out;
      for (const auto& [time, transform] : keys) out.push_back(time);
      return out;
    }
  };

  // Throws, naming the animation, if its keys do not span [open, close] evenly.
  static void check_keys(const Animation& animation, double open, double close) {
    if (const std::string problem = shutter_keys_problem(animation.times(), open, close); !problem.empty())
      throw SceneError(animation.where, problem);
  }

  Instantiator(const XmlNode& root, Vec3d render_origin, const std::string& source)
      : render_origin_(render_origin), resolver_(std::filesystem::path(source).parent_path()) {
    collect_ids(root, true);
    // The reader has checked each <path> and replaced its value by the folder found.
    for (const XmlNode& node : root.children)
      if (node.tag == "path") resolver_.add_folder(*node.attribute("value"));
  }

  ObjectValue build(const XmlNode& node) {
    // A scene of a million objects (instances) takes long to build: a stop
    // request is seen between objects.
    if (stop_request().load()) throw Interrupted("interrupted");
    // Nested objects and chains of references both recurse through here.
    if (depth_ >= kMaxSceneDepth)
      throw SceneError(node.where, "objects nested or referring to each other more than " +
                                       std::to_string(kMaxSceneDepth) + " deep");
    ++depth_;
    struct Leave {
      int& depth;
      ~Leave() { --depth; }
    } leave{depth_};
    if (const std::string* id = node.attribute("id")) {
      if (auto it = built_.find(*id); it != built_.end()) {
        // A group's shapes live in the group's space, the others in render space.
        if (placed_in_space(it->second) && shapes_in_group_.at(*id) != (in_group_ > 0))
          throw SceneError(node.where, "shape '" + *id +
                                           "' is used both inside a shapegroup and outside one; give each use its "
                                           "own shape");
        held_by_parent(held_of_id_[*id]);
        return it->second;
      }
      if (const auto at = std::find(building_.begin(), building_.end(), *id); at != building_.end()) {
        std::string cycle;
        for (auto it = at; it != building_.end(); ++it) cycle += "'" + *it + "' -> ";
        throw SceneError(node.where, "references form a cycle: " + cycle + "'" + *id + "'");
      }
      building_.push_back(*id);
    }
    held_.push_back({});
    ObjectValue obj = create(node);
    const Held held = holding(node, held_.back());
    held_.pop_back();
    held_by_parent(held);
    if (const std::string* id = node.attribute("id")) {
      building_.pop_back();
      built_[*id] = obj;
      held_of_id_[*id] = held;
      if (placed_in_space(obj)) shapes_in_group_[*id] = in_group_ > 0;
    }
    return obj;
  }

  ObjectValue resolve_ref(const XmlNode& ref) {
    ref.check_attributes({"id", "name"});
    const std::string& id = required_attribute(ref, "id");
    const auto it = ids_.find(id);
    if (it == ids_.end()) throw SceneError(ref.where, "reference to undefined id '" + id + "'");
    return build(*it->second);
  }

  std::vector<std::shared_ptr<Emitter>> emitters;  // every emitter built, area ones included
  std::vector<SourceLocation> emitter_places;      // where each of `emitters` was written
  std::vector<std::string> warnings;
  GivenValues integrator_values;       // what the last <integrator> built was given
  int textures = 0;                    // texture plugins built, for the scene features
  std::vector<GivenSpectrum> spectra;  // colours given as spectra, for the scene features
  std::vector<Animation> animations;   // timed against the shutter once the sensor is built
  std::set<const Emitter*> attached;   // area emitters a shape has taken, nested or by reference

 private:
  void collect_ids(const XmlNode& node, bool is_root) {
    if (!is_root && kObjectTags.count(node.tag))
      if (const std::string* id = node.attribute("id")) {
        if (ids_.count(*id))
          throw SceneError(node.where, "id '" + *id + "' is already used at " + ids_[*id]->where.str());
        ids_[*id] = &node;
      }
    for (const XmlNode& child : node.children) collect_ids(child, false);
  }

  ObjectValue create(const XmlNode& node) {
    node.check_attributes({"type", "id", "name"});
    const std::string& type = required_attribute(node, "type");
    const PluginInfo* info = Registry::instance().find(node.tag, type);
    if (!info)
      throw SceneError(node.where, "unknown " + node.tag + " type '" + type +
                                       "' (available: " + join_names(Registry::instance().names(node.tag)) + ")");
    Properties props(*info, node.where);
    props.set_warnings(&warnings);
    // A shapegroup's shapes stay in the group's own space; only the
    // instances placing them move to render space.
    props.set_render_origin(in_group_ > 0 ? Vec3d() : render_origin_);
    props.set_resolver(&resolver_);
    const bool group = node.tag == "shape" && type == "shapegroup";
    in_group_ += group;
    std::optional<Animation> animation;
    std::optional<Transform> shared_scale;  // a moving area light's
    for (const XmlNode& child : node.children) {
      if (child.tag == "animation")
        animation = read_animation(child, node, type);
      else
        add_child(props, child, node.tag);
    }
    in_group_ -= group;
    // A moving shape is built in its own space and placed by its keys; a
    // moving camera or light is built where its first key places it.
    if (animation) {
      if (props.has("to_world"))
        throw SceneError(animation->where,
                         "a " + node.tag + " takes to_world as a transform or as an animation, not both");
      animations.push_back(*animation);
      if (node.tag == "sensor" || node.tag == "emitter") {
        props.set("to_world", {ValueKind::Transform, animation->keys.front().second, animation->where});
      } else {
        props.set_render_origin(Vec3d());
        // An area light's shape is built with its keys' shared scale, so
        // that the keys move it rigidly, as MovingEmitter carries light.
        if (std::any_of(node.children.begin(), node.children.end(),
                        [](const XmlNode& child) { return child.tag == "emitter"; })) {
          shared_scale = shared_scale_of(*animation);
          props.set("to_world", {ValueKind::Transform, *shared_scale, animation->where});
        }
      }
    }

    std::shared_ptr<Plugin> plugin;
    try {
      plugin = info->create(props);
    } catch (const SceneError&) {
      throw;
    } catch (const Interrupted&) {
      throw;
    } catch (const std::exception& e) {
      throw SceneError(node.where, node.tag + " '" + type + "': " + e.what());
    }
    for (const std::string& name : info->ignored)
      if (props.has(name)) props.warn(name, "is ignored: " + find_ignored_param(node.tag, name)->why);
    if (node.tag == "shape") finish_shape(std::static_pointer_cast<Shape>(plugin), props, node);
    if (animation) plugin = moving(plugin, node.tag, *animation, shared_scale);
    if (node.tag == "emitter") {
      std::static_pointer_cast<Emitter>(plugin)->set_medium(props.child<Medium>("medium"));
      emitters.push_back(std::static_pointer_cast<Emitter>(plugin));
      emitter_places.push_back(node.where);
    }
    if (node.tag == "texture") ++textures;
    if (node.tag == "integrator") integrator_values = props.values();
    return {node.tag, plugin};
  }

  void add_child(Properties& props, const XmlNode& child, const std::string& owner) {
    if (child.tag == "spectrum" || child.tag == "blackbody") {
      const std::string name = required_attribute(child, "name");
      PropertyValue v = parse_spectrum_element(child, resolver_);
      if (v.spectrum) spectra.push_back({child.where, owner, name, v.spectrum});
      props.set(name, std::move(v));
    } else if (const auto kind = kValueTags.find(child.tag); kind != kValueTags.end()) {
      props.set(required_attribute(child, "name"), parse_value_element(child, kind->second));
    } else if (child.tag == "transform") {
      child.check_attributes({"name"});
      props.set(required_attribute(child, "name"), {ValueKind::Transform, parse_transform(child), child.where});
    } else if (kObjectTags.count(child.tag) || child.tag == "ref") {
      ObjectValue obj = child.tag == "ref" ? resolve_ref(child) : build(child);
      // A name makes the object a parameter only where the plugin declares
      // one by that name; elsewhere (a shape's named bsdf) it is a child.
      const std::string* name = child.attribute("name");
      if (name && props.info().param(*name))
        props.set(*name, {ValueKind::Object, obj, child.where});
      else
        props.add_child(obj, child.where, name ? *name : "");
    } else {
      throw SceneError(child.where, "unknown element <" + child.tag + ">");
    }
  }

  // <animation name="to_world"> with <transform time="..."> keys, on a
  // sensor, an emitter or a shape of the scene's own (an instance included;
  // not in a group, nor a group or a csg solid).
  Animation read_animation(const XmlNode& animation, const XmlNode& owner, const std::string& type) {
    animation.check_attributes({"name"});
    if (required_attribute(animation, "name") != "to_world")
      throw SceneError(animation.where, "only to_world can be animated, not '" +
                                            required_attribute(animation, "name").substr(0, 40) + "'");
    if (owner.tag != "shape" && owner.tag != "sensor" && owner.tag != "emitter")
      throw SceneError(animation.where,
                       "only shapes, sensors and emitters can move: a moving " + owner.tag + " means nothing");
    if (type == "shapegroup" || type == "csg" || in_group_ > 0)
      throw SceneError(animation.where, "a " + (in_group_ > 0 ? "shape in a shapegroup" : type) +
                                            " cannot move yet: animate a shape of the scene's own");
    Animation out{{}, animation.where};
    for (const XmlNode& key : animation.children) {
      if (key.tag != "transform")
        throw SceneError(key.where, "an <animation> holds only <transform time=\"...\"> keys, not <" + key.tag + ">");
      key.check_attributes({"time"});
      const double time =
          std::get<double>(parse_value_text(ValueKind::Float, required_attribute(key, "time"), key.where).value);
      out.keys.emplace_back(time, parse_transform(key));
    }
    if (const std::string problem = key_times_problem(out.times()); !problem.empty())
      throw SceneError(animation.where, problem);
    return out;
  }

  // The plugin carried by the animation's keys (in render space; a moving
  // area light's shape's without the scale it was built with).
  std::shared_ptr<Plugin> moving(const std::shared_ptr<Plugin>& plugin, const std::string& tag,
                                 const Animation& animation, const std::optional<Transform>& shared_scale) {
    std::vector<Transform> keys;
    for (const auto& [time, transform] : animation.keys)
      keys.push_back(Transform::translate(-render_origin_) * transform *
                     (shared_scale ? shared_scale->inverse() : Transform()));
    try {
      if (tag == "sensor") return std::make_shared<MovingSensor>(std::static_pointer_cast<Sensor>(plugin), keys);
      if (tag == "emitter")
        return std::make_shared<MovingEmitter>(std::static_pointer_cast<Emitter>(plugin), keys, keys.front());
      const auto shape = std::static_pointer_cast<Shape>(plugin);
      for (const Medium* medium : {shape->interior(), shape->exterior()})
        if (medium && !medium->is_homogeneous())
          throw SceneError(animation.where,
                           "a moving shape can bound homogeneous media only: a heterogeneous medium's density "
                           "stays where its own to_world puts it");
      if (shape->emitter()) move_area_light(*shape, keys);
      return std::make_shared<MovingShape>(shape, keys);
    } catch (const std::invalid_argument& e) {
      throw SceneError(animation.where, e.what());
    }
  }

  // The scale and shear every key of a moving area light's shape shares
  // (its first key's), or a SceneError naming the first key that differs.
  static Transform shared_scale_of(const Animation& animation) {
    std::vector<Transform> keys;
    for (const auto& [time, transform] : animation.keys) keys.push_back(transform);
    try {
      const AnimatedTransform motion(keys);
      if (const size_t k = motion.first_rescaled_key())
        throw SceneError(animation.where, "a moving area light's keys must share one scale and shear (key " +
                                              std::to_string(k) + "'s differs from the first's)");
      TransformParts scale = motion.parts().front();
      scale.q = {1, 0, 0, 0};
      scale.t = {0, 0, 0};
      return scale.transform();
    } catch (const std::invalid_argument& e) {
      throw SceneError(animation.where, std::string("an animation key is not invertible: ") + e.what());
    }
  }

  // The area light of a moving shape, built in the shape's own space,
  // carried by the shape's rigid keys: the shape's hits and the scene's
  // light list name the moving light instead.
  void move_area_light(Shape& shape, const std::vector<Transform>& rigid) {
    const Emitter* still = shape.emitter();
    for (auto& emitter : emitters)
      if (emitter.get() == still) {
        emitter = std::make_shared<MovingEmitter>(emitter, rigid, Transform());
        shape.set_emitter(emitter.get());
      }
  }

  // A shape with a place of its own (not a group, nor an instance, which a
  // group refuses anyway): in a group's space or in the scene's.
  static bool placed_in_space(const ObjectValue& obj) {
    if (obj.category != "shape") return false;
    const auto& shape = static_cast<const Shape&>(*obj.object);
    return !shape.is_group() && !shape.is_instance();
  }

  void finish_shape(const std::shared_ptr<Shape>& shape, const Properties& props, const XmlNode& node) {
    shape->set_media(props.get_object<Medium>("interior"), props.get_object<Medium>("exterior"));
    // Hits name a csg solid's operands, which would not know its media.
    if (shape->kind() == "csg" && shape->bounds_media())
      throw SceneError(node.where, "a csg shape cannot bound media: its operands' surfaces do not carry them");
    auto bsdf = props.child<Bsdf>("bsdf");
    if (!bsdf) {
      // A shape without a material is a grey diffuse one, as in Mitsuba,
      // unless it bounds media: then it is the media's index-matched boundary.
      bsdf = Registry::instance().create_default<Bsdf>("bsdf", shape->bounds_media() ? "null" : "diffuse", node.where);
    }
    if (const std::string why = shape->refused_material(*bsdf); !why.empty()) throw SceneError(node.where, why);
    shape->set_bsdf(bsdf);
    if (auto emitter = props.child<Emitter>("emitter")) {
      try {
        emitter->attach_shape(shape.get());
      } catch (const SceneError&) {
        throw;
      } catch (const std::exception& e) {
        throw SceneError(node.where, e.what());
      }
      shape->set_emitter(emitter.get());
      attached.insert(emitter.get());
      // It emits from the shape's outer side, into the exterior medium.
      if (shape->bounds_media()) emitter->set_medium(props.get_object<Medium>("exterior"));
    }
  }

  Vec3d render_origin_;
  FileResolver resolver_;
  // What an object holds: the levels of objects below and including it,
  // through references too (a chain of objects each referring to the one
  // before is as deep as it is long), and how many BSDFs and textures it
  // evaluates at each shading point, a referenced one as often as it is
  // referenced (a chain of blendbsdfs each referring twice to the one
  // before costs 2^n).
  struct Held {
    int levels = 0;
    double evaluations = 0;
  };
  static constexpr double kMaxEvaluations = 4096;
  static Held holding(const XmlNode& node, const Held& children) {
    const Held held{children.levels + 1, node.tag == "bsdf" || node.tag == "texture" ? children.evaluations + 1 : 0};
    if (held.levels > kMaxSceneDepth)
      throw SceneError(node.where, "objects nested or referring to each other more than " +
                                       std::to_string(kMaxSceneDepth) + " deep");
    if (held.evaluations > kMaxEvaluations) {
      char count[32];
      std::snprintf(count, sizeof count, "%.3g", held.evaluations);
      throw SceneError(node.where, "this " + node.tag + " holds, counting a referenced one each time it is used, " +
                                       count + " BSDFs and textures, all evaluated at every shading point; at most " +
                                       std::to_string(int(kMaxEvaluations)) + " are allowed");
    }
    return held;
  }
  void held_by_parent(const Held& held) {
    if (held_.empty()) return;
    held_.back().levels = std::max(held_.back().levels, held.levels);
    held_.back().evaluations += held.evaluations;
  }
  std::vector<Held> held_;  // what each object being built holds so far, innermost last
  std::map<std::string, Held> held_of_id_;
  int depth_ = 0;
  int in_group_ = 0;                             // shapegroups being built around the current object
  std::map<std::string, bool> shapes_in_group_;  // for each shape built with an id, whether inside a group
  std::map<std::string, const XmlNode*> ids_;
  std::map<std::string, ObjectValue> built_;
  std::vector<std::string> building_;  // the ids being built, outermost first
};

// Light selection and photon emission weigh emitters by power, in float.
void check_emitter_powers(const Scene& scene, const std::vector<SourceLocation>& places) {
  for (size_t i = 0; i < places.size(); ++i) {
    const Color power = scene.emitters()[i]->power();
    if (!std::isfinite(power.r + power.g + power.b)) {
      char watts[96];
      std::snprintf(watts, sizeof watts, "%.3g, %.3g, %.3g W", double(power.r), double(power.g), double(power.b));
      throw SceneError(places[i], std::string("the emitter's power (") + watts +
                                      ") overflows single precision; express the scene in other units");
    }
  }
}

// Where the camera stands, in double: the origin of render space, so that
// geometry far from the world's origin is stored in float relative to the
// camera, where its precision matters (as pbrt-v4 renders in camera-world
// space).
Vec3d camera_position(const XmlNode& root) {
  for (const XmlNode& node : root.children)
    if (node.tag == "sensor")
      for (const XmlNode& child : node.children)
        if (child.attribute("name") && *child.attribute("name") == "to_world") {
          if (child.tag == "transform") return parse_transform(child).point_double({0, 0, 0});
          // A moving camera's first key.
          if (child.tag == "animation" && !child.children.empty() && child.children.front().tag == "transform")
            return parse_transform(child.children.front()).point_double({0, 0, 0});
        }
  return {};
}

LoadedScene instantiate(const XmlNode& root, const std::string& source,
                        const std::vector<std::string>& unused_defines = {},
                        const std::vector<std::string>& upgrade_notes = {}) {
  const Vec3d origin = camera_position(root);
  Instantiator inst(root, origin, source);
  std::vector<std::shared_ptr<Shape>> shapes;
  std::shared_ptr<Sensor> sensor;
  std::shared_ptr<Integrator> integrator;
  std::shared_ptr<ToneOperator> tone_operator;
  // A top-level area emitter is a shape's if a shape refers to it, before
  // or after it in the file (Mitsuba instantiates the whole tree at once).
  std::vector<std::pair<const Emitter*, SourceLocation>> top_level_area;
  for (const XmlNode& node : root.children) {
    if (node.tag == "path") continue;
    if (!kObjectTags.count(node.tag) && node.tag != "ref")
      throw SceneError(node.where, "unexpected <" + node.tag + "> at the top level of a scene");
    if (node.tag == "ref") throw SceneError(node.where, "<ref> must be nested in an object");
    const ObjectValue obj = inst.build(node);
    if (node.tag == "shape") {
      // A group is drawn only where instances place it.
      if (!std::static_pointer_cast<Shape>(obj.object)->is_group())
        shapes.push_back(std::static_pointer_cast<Shape>(obj.object));
    } else if (node.tag == "sensor") {
      if (sensor) throw SceneError(node.where, "a scene may have only one sensor");
      sensor = std::static_pointer_cast<Sensor>(obj.object);
    } else if (node.tag == "integrator") {
      if (integrator) throw SceneError(node.where, "a scene may have only one integrator");
      integrator = std::static_pointer_cast<Integrator>(obj.object);
    } else if (node.tag == "tonemap") {
      if (tone_operator) throw SceneError(node.where, "a scene may have only one tonemap");
      tone_operator = std::static_pointer_cast<ToneOperator>(obj.object);
    } else if (node.tag == "emitter" && std::static_pointer_cast<Emitter>(obj.object)->is_area()) {
      top_level_area.emplace_back(std::static_pointer_cast<Emitter>(obj.object).get(), node.where);
    }
  }
  for (const auto& [emitter, where] : top_level_area)
    if (!inst.attached.count(emitter))
      throw SceneError(where, "an area emitter must be nested in a shape or referenced by one (<ref id=\"...\"/>)");
  if (!sensor) sensor = Registry::instance().create_default<Sensor>("sensor", "perspective", root.where);
  if (!integrator) integrator = make_integrator("path");
  for (const auto& animation : inst.animations)
    Instantiator::check_keys(animation, sensor->shutter_open(), sensor->shutter_close());
  auto scene = std::make_shared<Scene>(std::move(shapes), std::move(inst.emitters), std::move(sensor), source);
  if (const auto problem = scene_extent_problem(scene->bounds())) throw SceneError(root.where, *problem);
  check_emitter_powers(*scene, inst.emitter_places);
  scene->set_render_origin(origin);
  SceneFeatures features = analyze_scene(*scene, inst.textures > 0, inst.spectra);
  // <scene spectral="on|off|auto">: the file may decide the transport mode
  // (the command line's --spectral on|off still overrides it).
  if (const std::string* mode = root.attribute("spectral")) {
    if (*mode != "on" && *mode != "off" && *mode != "auto")
      throw SceneError(root.where, "<scene spectral='" + mode->substr(0, 40) + "'> must be on, off or auto");
    if (*mode != "auto") force_spectral(features, *mode == "on", "forced by the scene file");
  }
  scene->set_features(std::move(features));
  if (auto warning = clip_warning(scene->sensor().clip_planes(), scene->bounds()))
    inst.warnings.push_back(source + ": " + *warning);
  inst.warnings.insert(inst.warnings.begin(), upgrade_notes.begin(), upgrade_notes.end());
  for (const std::string& name : unused_defines)
    inst.warnings.push_back(source + ": -D " + name + " is not used by the scene (no $" + name + " in it)");
  return {std::move(scene), std::move(integrator), std::move(inst.integrator_values), std::move(tone_operator),
          std::move(inst.warnings)};
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

LoadedScene load_scene(const std::filesystem::path& file, const Defines& defines) {
  std::vector<std::string> unused, notes;
  XmlNode root = read_scene_xml(file, defines, &unused, &notes);
  return instantiate(root, file.string(), unused, notes);
}

LoadedScene load_scene_string(std::string_view xml, const std::filesystem::path& file_for_messages,
                              const Defines& defines) {
  std::vector<std::string> unused, notes;
  XmlNode root = read_scene_xml_string(xml, file_for_messages, defines, &unused, &notes);
  return instantiate(root, file_for_messages.string(), unused, notes);
}

Defines parse_defines(const std::vector<std::string>& items) {
  Defines out;
  for (const std::string& item : items) {
    const size_t eq = item.find('=');
    if (eq == std::string::npos || eq == 0)
      throw std::invalid_argument(shorten_quoted("-D expects name=value, got '" + item + "'"));
    out[item.substr(0, eq)] = item.substr(eq + 1);
  }
  return out;
}

std::shared_ptr<Integrator> make_integrator(const std::string& spec, const GivenValues& inherited) {
  const size_t colon = spec.find(':');
  const std::string name = spec.substr(0, colon);
  const PluginInfo* info = Registry::instance().find("integrator", name);
  if (!info)
    throw std::invalid_argument("unknown integrator '" + name +
                                "' (available: " + join_names(Registry::instance().names("integrator")) + ")");
  const SourceLocation where{"--integrator " + spec, 0};
  Properties props(*info, where);
  std::set<std::string> named;
  if (colon != std::string::npos) {
    std::istringstream list(spec.substr(colon + 1));
    for (std::string item; std::getline(list, item, ',');) {
      const size_t eq = item.find('=');
      if (eq == std::string::npos || eq == 0) throw SceneError(where, "expected name=value, got '" + item + "'");
      const std::string param = item.substr(0, eq);
      const ParamSpec* declared = info->param(param);
      // Unknown names fall through to set(), which lists what is accepted.
      const ValueKind kind = declared ? default_kind(declared->type) : ValueKind::String;
      props.set(param, parse_value_text(kind, item.substr(eq + 1), where));
      named.insert(param);
    }
  }
  for (const auto& [name, value] : inherited)
    if (info->param(name) && !named.count(name)) props.set(name, value);
  return std::dynamic_pointer_cast<Integrator>(info->create(props));
}

}  // namespace caustica
