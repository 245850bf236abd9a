#include "core/loader/xml_reader.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <fstream>
#include <optional>
#include <pugixml.hpp>
#include <set>
#include <sstream>
#include <utility>
#include <vector>

#include "core/loader/upgrade_0x.h"
#include "core/registry/file_resolver.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

namespace fs = std::filesystem;
using Defines = std::map<std::string, std::string>;

bool is_upper(char c) { return std::isupper(static_cast<unsigned char>(c)) != 0; }
bool is_lower(char c) { return std::islower(static_cast<unsigned char>(c)) != 0; }
bool is_name_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0 || c == '_'; }
bool is_name_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; }

bool is_parameter_name(std::string_view name) {
  return !name.empty() && is_name_start(name[0]) && std::all_of(name.begin(), name.end(), is_name_char);
}

// pugixml only reports byte offsets; every node we hand on needs a line.
class LineTable {
 public:
  explicit LineTable(std::string_view text) {
    for (size_t i = 0; i < text.size(); ++i)
      if (text[i] == '\n') newlines_.push_back(i);
  }

  int line_of(std::ptrdiff_t offset) const {
    if (offset < 0) return 0;
    auto it = std::lower_bound(newlines_.begin(), newlines_.end(), static_cast<size_t>(offset));
    return static_cast<int>(it - newlines_.begin()) + 1;
  }

 private:
  std::vector<size_t> newlines_;
};

// Returns the major version, or nothing if `version` is not MAJOR.MINOR.PATCH.
std::optional<int> parse_major_version(std::string_view version) {
  int major = 0;
  int parts = 0;
  size_t start = 0;
  while (true) {
    size_t end = std::min(version.find('.', start), version.size());
    std::string_view part = version.substr(start, end - start);
    if (part.empty() || !std::all_of(part.begin(), part.end(), [](char c) { return c >= '0' && c <= '9'; }))
      return std::nullopt;
    if (parts == 0 && std::from_chars(part.data(), part.data() + part.size(), major).ec != std::errc()) {
      return std::nullopt;
    }
    ++parts;
    if (end == version.size()) break;
    start = end + 1;
  }
  if (parts != 3) return std::nullopt;
  return major;
}

// The renames Mitsuba 3 applies to 0.x files that need no knowledge of the plugin.
void upgrade_from_0x(XmlNode& node) {
  if (node.tag == "lookAt")
    node.tag = "lookat";
  else if (node.tag == "srgb")
    upgrade_srgb(node);
  for (auto& [key, value] : node.attributes)
    if (key == "name") value = camel_to_snake(value);
}

// Identifies a file for include-cycle detection even when reached by different relative paths.
fs::path identity_of(const fs::path& file) {
  std::error_code ec;
  fs::path canonical = fs::weakly_canonical(file, ec);
  return ec ? file.lexically_normal() : canonical;
}

struct FileContext {
  fs::path path;
  std::string name;
  LineTable lines;
  bool upgrade = false;

  SourceLocation at(const pugi::xml_node& node) const { return {name, lines.line_of(node.offset_debug())}; }
};

// Parameters are shared across included files, so one reader serves the whole tree.
class Reader {
 public:
  Reader(const Defines& defines, const fs::path& main_file)
      : params_(defines), defines_(defines), resolver_(main_file.parent_path()) {}

  // What upgrading 0.x files dropped, one line each.
  const std::vector<std::string>& upgrade_notes() const { return notes_; }

  // The names -D defined that no $name has used so far.
  std::vector<std::string> unused_defines() const {
    std::vector<std::string> out;
    for (const auto& [name, value] : defines_)
      if (!used_.count(name)) out.push_back(name);
    return out;
  }

  XmlNode read_file(const fs::path& file, const SourceLocation& blame, const std::string& what) {
    std::error_code ec;
    // A device or a pipe (/dev/zero) would be read forever.
    if (fs::exists(file, ec) && !fs::is_regular_file(file, ec))
      throw SceneError(blame, "the " + what + " '" + file.string() + "' is not a regular file");
    std::ifstream in(file, std::ios::binary);
    if (!in) throw SceneError(blame, "cannot open " + what + " '" + file.string() + "'");
    std::ostringstream contents;
    contents << in.rdbuf();
    return read_text(contents.str(), file);
  }

  XmlNode read_text(std::string_view text, const fs::path& file) {
    FileContext ctx{file, file.string(), LineTable(text)};
    pugi::xml_document doc;
    pugi::xml_parse_result result = doc.load_buffer(text.data(), text.size(), pugi::parse_default, pugi::encoding_utf8);
    if (!result)
      throw SceneError({ctx.name, ctx.lines.line_of(result.offset)},
                       std::string("malformed XML: ") + result.description());
    pugi::xml_node root = doc.document_element();
    if (std::string_view(root.name()) != "scene")
      throw SceneError(ctx.at(root), "root element must be <scene>, found <" + std::string(root.name()) + ">");

    if (!file.empty()) open_files_.emplace_back(identity_of(file), ctx.name);
    define_defaults(root, ctx);
    if (pugi::xml_attribute version = root.attribute("version")) {
      std::string text_version = substitute(version.value(), ctx.at(root));
      std::optional<int> major = parse_major_version(text_version);
      if (!major) throw SceneError(ctx.at(root), "invalid version '" + text_version + "' (expected MAJOR.MINOR.PATCH)");
      ctx.upgrade = *major < 2;
    }
    XmlNode node = convert(root, ctx, 0);
    if (!file.empty()) open_files_.pop_back();
    return node;
  }

 private:
  // Defaults are gathered before anything else so a parameter may be used above its <default>.
  void define_defaults(const pugi::xml_node& root, const FileContext& ctx) {
    for (pugi::xml_node child : root.children("default")) {
      SourceLocation where = ctx.at(child);
      pugi::xml_attribute name = child.attribute("name");
      pugi::xml_attribute value = child.attribute("value");
      if (!name || !value) throw SceneError(where, "<default> needs both a 'name' and a 'value' attribute");
      if (!is_parameter_name(name.value()))
        throw SceneError(where, "invalid parameter name '" + std::string(name.value()) + "' in <default>");
      // try_emplace keeps what -D (or an earlier default) already set.
      params_.try_emplace(name.value(), substitute(value.value(), where));
    }
  }

  std::string substitute(std::string_view value, const SourceLocation& where) {
    std::string out;
    size_t i = 0;
    while (i < value.size()) {
      if (value[i] != '$' || i + 1 == value.size() || !is_name_start(value[i + 1])) {
        out += value[i++];
        continue;
      }
      size_t end = i + 2;
      while (end < value.size() && is_name_char(value[end])) ++end;
      std::string name(value.substr(i + 1, end - i - 1));
      auto found = params_.find(name);
      if (found == params_.end())
        throw SceneError(where,
                         "undefined parameter '$" + name + "' (define it with <default> or -D " + name + "=value)");
      out += found->second;
      used_.insert(name);
      i = end;
    }
    return out;
  }

  // `depth` counts the elements above this one; bounded, so that a hostile
  // file cannot exhaust the stack.
  XmlNode convert(const pugi::xml_node& element, const FileContext& ctx, int depth) {
    const bool is_root = depth == 0;
    if (depth > kMaxSceneDepth)
      throw SceneError(ctx.at(element), "<" + std::string(element.name()) + "> is nested more than " +
                                            std::to_string(kMaxSceneDepth) + " elements deep");
    XmlNode node{element.name(), {}, {}, ctx.at(element)};
    for (pugi::xml_attribute attribute : element.attributes()) {
      if (node.attribute(attribute.name()))
        throw SceneError(node.where, "<" + node.tag + "> has two '" + attribute.name() + "' attributes");
      node.attributes.emplace_back(attribute.name(), substitute(attribute.value(), node.where));
    }
    if (ctx.upgrade) upgrade_from_0x(node);
    for (pugi::xml_node child : element.children()) {
      if (child.type() != pugi::node_element) continue;
      std::string_view tag = child.name();
      if (tag == "default") {
        if (!is_root) throw SceneError(ctx.at(child), "<default> must be a direct child of <scene>");
      } else if (tag == "include") {
        splice_include(child, ctx, node.children);
      } else if (tag == "path") {
        if (!is_root) throw SceneError(ctx.at(child), "<path> must be a direct child of <scene>");
        node.children.push_back(search_folder(convert(child, ctx, depth + 1)));
      } else {
        node.children.push_back(convert(child, ctx, depth + 1));
      }
    }
    if (ctx.upgrade && node.attribute("type")) upgrade_object_from_0x(node, notes_);
    return node;
  }

  // A <path value="folder"/>: later includes, and every file the scene
  // names, are looked for there too. Its value becomes the folder found.
  XmlNode search_folder(XmlNode path) {
    path.check_attributes({"value"});
    const std::string* value = path.attribute("value");
    if (!value) throw SceneError(path.where, "<path> needs a 'value' attribute");
    const fs::path folder = resolver_.resolve(*value, path.where.file);
    std::error_code ec;
    if (!fs::is_directory(folder, ec)) throw SceneError(path.where, "<path> '" + folder.string() + "' is not a folder");
    resolver_.add_folder(folder);
    path.attributes = {{"value", folder.string()}};
    return path;
  }

  void splice_include(const pugi::xml_node& include, const FileContext& ctx, std::vector<XmlNode>& out) {
    SourceLocation where = ctx.at(include);
    pugi::xml_attribute filename = include.attribute("filename");
    if (!filename) throw SceneError(where, "<include> needs a 'filename' attribute");
    fs::path target = resolver_.resolve(substitute(filename.value(), where), ctx.path);

    fs::path identity = identity_of(target);
    auto open = std::find_if(open_files_.begin(), open_files_.end(),
                             [&](const auto& entry) { return entry.first == identity; });
    if (open != open_files_.end()) {
      std::string chain;
      for (auto it = open; it != open_files_.end(); ++it) chain += it->second + " -> ";
      throw SceneError(where, "include cycle: " + chain + target.string());
    }

    XmlNode included = read_file(target, where, "included file");
    for (XmlNode& child : included.children) out.push_back(std::move(child));
  }

  Defines params_;
  const Defines& defines_;
  std::set<std::string> used_;
  std::vector<std::pair<fs::path, std::string>> open_files_;  // identity, name for messages
  FileResolver resolver_;
  std::vector<std::string> notes_;
};

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

std::string camel_to_snake(std::string_view name) {
  std::string out;
  for (size_t i = 0; i < name.size(); ++i) {
    char c = name[i];
    if (is_upper(c) && i > 0) {
      // A word starts at lower->Upper, and at the last capital of an acronym
      // followed by a word ("IORValue" -> "ior_value"), so acronyms stay whole.
      bool after_lower = is_lower(name[i - 1]);
      bool ends_acronym = is_upper(name[i - 1]) && i + 1 < name.size() && is_lower(name[i + 1]);
      if ((after_lower || ends_acronym) && out.back() != '_') out += '_';
    }
    out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  return out;
}

XmlNode read_scene_xml(const std::filesystem::path& file, const std::map<std::string, std::string>& defines,
                       std::vector<std::string>* unused_defines, std::vector<std::string>* upgrade_notes) {
  Reader reader(defines, file);
  XmlNode root = reader.read_file(file, {file.string(), 0}, "scene file");
  if (unused_defines) *unused_defines = reader.unused_defines();
  if (upgrade_notes) *upgrade_notes = reader.upgrade_notes();
  return root;
}

XmlNode read_scene_xml_string(std::string_view text, const std::filesystem::path& file_for_messages,
                              const std::map<std::string, std::string>& defines,
                              std::vector<std::string>* unused_defines, std::vector<std::string>* upgrade_notes) {
  Reader reader(defines, file_for_messages);
  XmlNode root = reader.read_text(text, file_for_messages);
  if (unused_defines) *unused_defines = reader.unused_defines();
  if (upgrade_notes) *upgrade_notes = reader.upgrade_notes();
  return root;
}

}  // namespace caustica
