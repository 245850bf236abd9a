// gridvolume: values on a voxel grid read from a Mitsuba .vol file or a
// grid of an OpenVDB file, interpolated trilinearly between voxel centres
// (or taken from the nearest voxel) and clamped at the grid's border, as
// Mitsuba 3 samples its grids. A .vol grid fills the unit cube mapped by
// to_world (or, with use_grid_bbox, the file's bounding box, then
// to_world); an OpenVDB grid is held densely over the box of its active
// voxels, placed where its own transform puts them, then by to_world.
// Outside the grid's box the value is 0.
//
//   <volume type="gridvolume" name="sigma_t">
//       <string name="filename" value="smoke.vol"/>
//       <transform name="to_world"><scale value="0.3"/></transform>
//   </volume>
//   <volume type="gridvolume" name="sigma_t">
//       <string name="filename" value="cloud.vdb"/>
//       <string name="grid" value="density"/>
//   </volume>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>

#include "core/files/input_file.h"
#include "core/math/transform.h"
#include "core/media/vdb_file.h"
#include "core/media/vol_file.h"
#include "core/media/volume.h"
#include "core/registry/properties.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

class GridVolume final : public Volume {
 public:
  explicit GridVolume(const Properties& props) {
    const std::string filter = props.get_string("filter_type");
    if (filter != "trilinear" && filter != "nearest")
      throw props.error("filter_type", "must be trilinear or nearest, not '" + filter + "'");
    nearest_ = filter == "nearest";
    const std::filesystem::path file = props.get_path("filename");
    // A missing file is named by its reader, which says what it expected.
    if (const std::string problem = input_file_problem(file); !problem.empty() && problem != "not found")
      throw props.error("filename", "volume file '" + file.string() + "' " + problem);
    const bool vdb = is_vdb(file);
    const std::string grid_name = props.get_string("grid");
    try {
      grid_ = vdb ? read_vdb_file(file, grid_name) : read_vol_file(file);
    } catch (const std::runtime_error& e) {
      throw props.error("filename", e.what());
    }
    Transform to_world = props.get_transform("to_world");
    if (props.get_bool("use_grid_bbox") || vdb) {
      const Bounds3& b = grid_.bbox;
      if (!(b.hi.x > b.lo.x && b.hi.y > b.lo.y && b.hi.z > b.lo.z))
        throw props.error("use_grid_bbox", "the file's bounding box is empty");
      to_world = to_world * Transform::translate(Vec3d(b.lo.x, b.lo.y, b.lo.z)) *
                 Transform::scale(Vec3d(b.hi.x - b.lo.x, b.hi.y - b.lo.y, b.hi.z - b.lo.z));
    }
    to_local_ = to_world.inverse();
    props.get_bool("raw");
    props.get_bool("accel");
  }

  Color eval(Vec3 p) const override {
    const Vec3 l = local(p);
    if (!(l.x >= 0 && l.x <= 1 && l.y >= 0 && l.y <= 1 && l.z >= 0 && l.z <= 1)) return {};
    if (nearest_) return voxel(cell(l.x, grid_.nx), cell(l.y, grid_.ny), cell(l.z, grid_.nz));
    // Continuous voxel coordinates: voxel i's centre lies at i + 0.5.
    const float x = l.x * grid_.nx - 0.5f, y = l.y * grid_.ny - 0.5f, z = l.z * grid_.nz - 0.5f;
    const float fx = std::floor(x), fy = std::floor(y), fz = std::floor(z);
    const float wx = x - fx, wy = y - fy, wz = z - fz;
    const int x0 = int(fx), y0 = int(fy), z0 = int(fz);
    Color sum;
    for (int k = 0; k < 8; ++k) {
      const int dx = k & 1, dy = (k >> 1) & 1, dz = k >> 2;
      const float w = (dx ? wx : 1 - wx) * (dy ? wy : 1 - wy) * (dz ? wz : 1 - wz);
      if (w > 0)
        sum +=
            voxel(clamp_index(x0 + dx, grid_.nx), clamp_index(y0 + dy, grid_.ny), clamp_index(z0 + dz, grid_.nz)) * w;
    }
    return sum;
  }

  bool is_constant() const override { return false; }
  bool is_chromatic() const override { return grid_.channels == 3; }

  float max_in(const Bounds3& c) const override {
    // Every voxel whose value a point of the cell can interpolate.
    const auto range = [](float lo, float hi, int n, int* first, int* last) {
      *first = std::clamp(int(std::floor(lo * n - 0.5f)), 0, n - 1);
      *last = std::clamp(int(std::floor(hi * n - 0.5f)) + 1, 0, n - 1);
    };
    int x0, x1, y0, y1, z0, z1;
    range(c.lo.x, c.hi.x, grid_.nx, &x0, &x1);
    range(c.lo.y, c.hi.y, grid_.ny, &y0, &y1);
    range(c.lo.z, c.hi.z, grid_.nz, &z0, &z1);
    float m = 0;
    for (int z = z0; z <= z1; ++z)
      for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x)
          for (int ch = 0; ch < grid_.channels; ++ch) m = std::max(m, grid_.at(x, y, z, ch));
    // Interpolation is a convex combination of these values, but its weights'
    // rounding may carry it a few units in the last place beyond them.
    return m * (1 + 1e-6f);
  }

  Vec3 local(Vec3 p) const override { return to_local_.point(Vec3d(p.x, p.y, p.z)); }
  Vec3 local_vector(Vec3 v) const override { return to_local_.vector(v); }
  Vec3 resolution() const override { return {float(grid_.nx), float(grid_.ny), float(grid_.nz)}; }

 private:
  static bool is_vdb(const std::filesystem::path& file) {
    std::string ext = file.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext == ".vdb";
  }
  static int clamp_index(int i, int n) { return std::clamp(i, 0, n - 1); }
  static int cell(float l, int n) { return clamp_index(int(l * n), n); }

  Color voxel(int x, int y, int z) const {
    if (grid_.channels == 1) return Color(grid_.at(x, y, z, 0));
    return {grid_.at(x, y, z, 0), grid_.at(x, y, z, 1), grid_.at(x, y, z, 2)};
  }

  VolGrid grid_;
  Transform to_local_;
  bool nearest_ = false;
};

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(
    GridVolume, "volume", "gridvolume",
    {{"filename", ParamType::String, std::nullopt,
      "the Mitsuba .vol file (1 or 3 channels of 32-bit floats), or an OpenVDB .vdb file"},
     {"grid", ParamType::String, "density", "the grid to read from a .vdb file (float or vec3s values)"},
     {"filter_type", ParamType::String, "trilinear", "trilinear (between voxel centres) or nearest"},
     {"to_world", ParamType::Transform, "",
      "maps the unit cube (or, with use_grid_bbox, the file's box) into the scene"},
     {"use_grid_bbox", ParamType::Boolean, "false",
      "place the grid at the bounding box its file declares (always so for .vdb files)"},
     {"raw", ParamType::Boolean, "false", "accepted; values are always used as stored here"},
     {"accel", ParamType::Boolean, "true", "accepted; interpolation is always done in software here"}},
    {});

}  // namespace caustica
