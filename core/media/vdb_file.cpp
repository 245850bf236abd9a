#include "core/media/vdb_file.h"

#include <stdexcept>

#ifdef CAUSTICA_HAVE_OPENVDB
#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>

#include <cmath>
#include <mutex>

#include "core/media/vdb_header_check.h"
#endif

namespace caustica {

#ifdef CAUSTICA_HAVE_OPENVDB

namespace {
namespace CAUSTICA_UNITY_ID {

// As for .vol files and images: 2^28 values at most.
constexpr uint64_t kMaxValues = uint64_t(1) << 28;

template <typename GridType, typename Store>
void fill_dense(const GridType& grid, const openvdb::CoordBBox& box, Store&& store) {
  const auto access = grid.getConstAccessor();
  size_t i = 0;
  for (int z = box.min().z(); z <= box.max().z(); ++z)
    for (int y = box.min().y(); y <= box.max().y(); ++y)
      for (int x = box.min().x(); x <= box.max().x(); ++x) store(i++, access.getValue(openvdb::Coord(x, y, z)));
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

bool reads_vdb_files() { return true; }

VolGrid read_vdb_file(const std::filesystem::path& file, const std::string& grid_name) {
  const auto fail = [&](const std::string& problem) { return std::runtime_error(file.string() + ": " + problem); };
  static std::once_flag initialised;
  std::call_once(initialised, [] { openvdb::initialize(); });

  if (const std::string problem = vdb_header_problem(file); !problem.empty()) throw fail(problem);
  openvdb::GridBase::Ptr base;
  try {
    openvdb::io::File in(file.string());
    in.open(false);
    if (!in.hasGrid(grid_name)) {
      std::string names;
      for (auto it = in.beginName(); it != in.endName(); ++it) names += (names.empty() ? "" : ", ") + *it;
      throw fail("has no grid named '" + grid_name + "' (its grids: " + (names.empty() ? "none" : names) + ")");
    }
    base = in.readGrid(grid_name);
  } catch (const openvdb::Exception& e) {
    throw fail(std::string("cannot be read as an OpenVDB file (") + e.what() + ")");
  }

  VolGrid grid;
  const auto floats = openvdb::gridPtrCast<openvdb::FloatGrid>(base);
  const auto vectors = openvdb::gridPtrCast<openvdb::Vec3SGrid>(base);
  if (!floats && !vectors)
    throw fail("grid '" + grid_name + "' holds values of type " + base->valueType() + "; float and vec3s are read");
  grid.channels = floats ? 1 : 3;

  const openvdb::math::Transform& transform = base->transform();
  const openvdb::Vec3d origin = transform.indexToWorld(openvdb::Vec3d(0, 0, 0));
  for (int axis = 0; axis < 3; ++axis) {
    openvdb::Vec3d step(0, 0, 0);
    step[axis] = 1;
    const openvdb::Vec3d w = transform.indexToWorld(step) - origin;
    const bool aligned = w[axis] > 0 && w[(axis + 1) % 3] == 0 && w[(axis + 2) % 3] == 0;
    if (!transform.isLinear() || !aligned)
      throw fail("grid '" + grid_name + "' has a " + transform.mapType() +
                 " transform whose voxels are not axis-aligned boxes; only scaled and translated grids are read");
  }

  const openvdb::CoordBBox box = base->evalActiveVoxelBoundingBox();
  if (box.empty()) throw fail("grid '" + grid_name + "' has no active voxel");
  const openvdb::Coord dim = box.dim();
  grid.nx = dim.x();
  grid.ny = dim.y();
  grid.nz = dim.z();
  const uint64_t values = uint64_t(grid.nx) * uint64_t(grid.ny) * uint64_t(grid.nz) * uint64_t(grid.channels);
  if (values > kMaxValues)
    throw fail("grid '" + grid_name + "' spans " + std::to_string(grid.nx) + " x " + std::to_string(grid.ny) + " x " +
               std::to_string(grid.nz) + " voxels with " + std::to_string(grid.channels) +
               " channels, more than 2^28 values to hold densely");
  // Voxel i covers index coordinates [i - 0.5, i + 0.5].
  const openvdb::Vec3d lo = transform.indexToWorld(box.min().asVec3d() - openvdb::Vec3d(0.5));
  const openvdb::Vec3d hi = transform.indexToWorld(box.max().asVec3d() + openvdb::Vec3d(0.5));
  grid.bbox.lo = {float(lo.x()), float(lo.y()), float(lo.z())};
  grid.bbox.hi = {float(hi.x()), float(hi.y()), float(hi.z())};

  grid.values.resize(size_t(values));
  const auto check = [&](float v, size_t i) {
    if (!(v >= 0) || !std::isfinite(v)) {
      const size_t voxel = i / size_t(grid.channels);
      const openvdb::Coord at =
          box.min() + openvdb::Coord(int(voxel % size_t(grid.nx)), int(voxel / size_t(grid.nx) % size_t(grid.ny)),
                                     int(voxel / (size_t(grid.nx) * size_t(grid.ny))));
      throw fail("grid '" + grid_name + "' holds the value " + std::to_string(v) + " at voxel (" +
                 std::to_string(at.x()) + ", " + std::to_string(at.y()) + ", " + std::to_string(at.z()) +
                 "); values must be finite and at least 0");
    }
    grid.values[i] = v;
  };
  if (floats)
    fill_dense(*floats, box, [&](size_t i, float v) { check(v, i); });
  else
    fill_dense(*vectors, box, [&](size_t i, const openvdb::Vec3s& v) {
      for (int c = 0; c < 3; ++c) check(v[c], 3 * i + size_t(c));
    });
  return grid;
}

#else

bool reads_vdb_files() { return false; }

VolGrid read_vdb_file(const std::filesystem::path& file, const std::string&) {
  throw std::runtime_error(file.string() +
                           ": this build of caustica reads no OpenVDB files (libopenvdb-dev was not installed when it "
                           "was configured; scripts/install-deps.sh installs it)");
}

#endif

}  // namespace caustica
