// gridvolume reading OpenVDB files: grids written here with OpenVDB's own
// API, read back through the plugin. Values land where the file's transform
// puts their voxels (nearest and trilinear lookups at voxel centres give
// the values written, between centres their interpolation), vec3s grids
// are chromatic, a heterogeneous medium over a uniform block has the
// Beer-Lambert transmittance (z-test at 0.1%, fixed seed), and each bad
// file or grid is refused with its message.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "core/media/vdb_file.h"
#include "tests/support/media.h"
#include "tests/support/samplers.h"
#include "tests/support/thrown_message.h"
#include "tests/support/z_test.h"

#ifdef CAUSTICA_HAVE_OPENVDB
#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>
#endif

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

using testing::HasSubstr;

std::filesystem::path temp_file(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / "caustica_vdb_volume_test";
  std::filesystem::create_directories(dir);
  return dir / name;
}

std::string volume_error(const std::filesystem::path& file, const std::string& grid = "density") {
  return test::thrown_message<std::exception>([&] { test::make_grid_volume(file, "trilinear", grid); });
}

#ifdef CAUSTICA_HAVE_OPENVDB

void write_grids(const std::filesystem::path& file, const openvdb::GridPtrVec& grids) {
  openvdb::initialize();
  openvdb::io::File out(file.string());
  out.write(grids);
  out.close();
}

// Voxels of size 0.25 at index (2..5, -1..2, 0..3), the index origin at
// world (1, -2, 0.5).
constexpr int kLo[3] = {2, -1, 0}, kHi[3] = {5, 2, 3};
const openvdb::Vec3d kOrigin(1, -2, 0.5);
constexpr double kVoxel = 0.25;

float value_at(int x, int y, int z) { return 0.1f * float(x) + 0.01f * float(y + 3) + 0.001f * float(z); }

Vec3 centre(int x, int y, int z) {
  return {float(kOrigin.x() + kVoxel * x), float(kOrigin.y() + kVoxel * y), float(kOrigin.z() + kVoxel * z)};
}

openvdb::math::Transform::Ptr placement() {
  auto t = openvdb::math::Transform::createLinearTransform(kVoxel);
  t->postTranslate(kOrigin);
  return t;
}

std::filesystem::path ramp_file() {
  auto grid = openvdb::FloatGrid::create(0.0f);
  grid->setName("density");
  grid->setTransform(placement());
  auto access = grid->getAccessor();
  for (int z = kLo[2]; z <= kHi[2]; ++z)
    for (int y = kLo[1]; y <= kHi[1]; ++y)
      for (int x = kLo[0]; x <= kHi[0]; ++x) access.setValue({x, y, z}, value_at(x, y, z));
  const auto file = temp_file("ramp.vdb");
  write_grids(file, {grid});
  return file;
}

TEST(VdbVolume, ValuesLandWhereTheTransformPutsThem) {
  const auto file = ramp_file();
  const auto nearest = test::make_grid_volume(file, "nearest");
  const auto trilinear = test::make_grid_volume(file, "trilinear");
  EXPECT_FALSE(nearest->is_chromatic());
  for (int z = kLo[2]; z <= kHi[2]; ++z)
    for (int y = kLo[1]; y <= kHi[1]; ++y)
      for (int x = kLo[0]; x <= kHi[0]; ++x) {
        EXPECT_EQ(nearest->eval(centre(x, y, z)).g, value_at(x, y, z)) << x << " " << y << " " << z;
        EXPECT_NEAR(trilinear->eval(centre(x, y, z)).g, value_at(x, y, z), 1e-6) << x << " " << y << " " << z;
      }
  // Halfway between two centres along each axis, and at the middle of eight.
  const Vec3 mid = (centre(3, 0, 1) + centre(4, 1, 2)) * 0.5f;
  double sum = 0;
  for (int k = 0; k < 8; ++k) sum += value_at(3 + (k & 1), (k >> 1) & 1, 1 + (k >> 2));
  EXPECT_NEAR(trilinear->eval(mid).g, sum / 8, 1e-6);
  EXPECT_NEAR(trilinear->eval((centre(2, 0, 0) + centre(2, 0, 1)) * 0.5f).g,
              (value_at(2, 0, 0) + value_at(2, 0, 1)) / 2, 1e-6);
  // The box of active voxels ends half a voxel past the outer centres.
  EXPECT_GT(nearest->eval(centre(kHi[0], 0, 0) + Vec3(0.12f, 0, 0)).g, 0);
  EXPECT_EQ(nearest->eval(centre(kHi[0], 0, 0) + Vec3(0.13f, 0, 0)).g, 0);
  EXPECT_EQ(nearest->eval(centre(kLo[0], 0, 0) - Vec3(0.13f, 0, 0)).g, 0);
}

TEST(VdbVolume, Vec3GridsAreChromatic) {
  auto grid = openvdb::Vec3SGrid::create(openvdb::Vec3s(0));
  grid->setName("albedo");
  grid->setTransform(placement());
  grid->getAccessor().setValue({2, 0, 0}, openvdb::Vec3s(0.2f, 0.5f, 0.9f));
  const auto file = temp_file("albedo.vdb");
  write_grids(file, {grid});
  const auto volume = test::make_grid_volume(file, "nearest", "albedo");
  EXPECT_TRUE(volume->is_chromatic());
  const Color c = volume->eval(centre(2, 0, 0));
  EXPECT_EQ(c, Color(0.2f, 0.5f, 0.9f));
}

TEST(VdbVolume, UniformBlockHasBeerLambertTransmittance) {
  // sigma_t 2 over the unit cube [0, 1]^3 as 4^3 voxels of 0.25.
  auto grid = openvdb::FloatGrid::create(0.0f);
  grid->setName("density");
  grid->setTransform(openvdb::math::Transform::createLinearTransform(kVoxel));
  grid->fill(openvdb::CoordBBox({0, 0, 0}, {3, 3, 3}), 2.0f);
  const auto file = temp_file("block.vdb");
  write_grids(file, {grid});
  // Index 0's voxel spans [-0.125, 0.125]: the block spans [-0.125, 0.875].
  const auto medium = test::make_medium(
      "<medium type='heterogeneous'><volume type='gridvolume' name='sigma_t'><string name='filename' value='" +
      file.string() + "'/></volume><float name='albedo' value='0.5'/></medium>");
  auto sampler = test::make_sampler("independent");
  const Ray ray{{-1, 0.4f, 0.4f}, {1, 0, 0}};
  const int n = 20000;
  double sum = 0, sum2 = 0;
  for (int i = 0; i < n; ++i) {
    sampler->start_sample(SampleKey::camera({0, 0}), uint64_t(i), 5);
    const double tr = medium->transmittance(ray, 3, *sampler).g;
    sum += tr;
    sum2 += tr * tr;
  }
  const double mean = sum / n, standard_error = std::sqrt((sum2 / n - mean * mean) / n);
  EXPECT_LT(std::abs(mean - std::exp(-2.0)), test::two_sided_z_critical(0.001) * standard_error + 1e-7) << mean;
}

TEST(VdbVolume, BadGridsAreRefused) {
  auto smoke = openvdb::FloatGrid::create(0.0f);
  smoke->setName("smoke");
  smoke->getAccessor().setValue({0, 0, 0}, 1.0f);
  const auto named = temp_file("named.vdb");
  write_grids(named, {smoke});
  EXPECT_THAT(volume_error(named), HasSubstr("named.vdb: has no grid named 'density' (its grids: smoke)"));

  auto ints = openvdb::Int32Grid::create(0);
  ints->setName("density");
  ints->getAccessor().setValue({0, 0, 0}, 1);
  const auto int_file = temp_file("ints.vdb");
  write_grids(int_file, {ints});
  EXPECT_THAT(volume_error(int_file), HasSubstr("grid 'density' holds values of type int32; float and vec3s are read"));

  auto empty = openvdb::FloatGrid::create(0.0f);
  empty->setName("density");
  const auto empty_file = temp_file("empty.vdb");
  write_grids(empty_file, {empty});
  EXPECT_THAT(volume_error(empty_file), HasSubstr("grid 'density' has no active voxel"));

  auto negative = openvdb::FloatGrid::create(0.0f);
  negative->setName("density");
  negative->getAccessor().setValue({3, 0, 1}, -1.0f);
  negative->getAccessor().setValue({4, 0, 1}, 1.0f);
  const auto negative_file = temp_file("negative.vdb");
  write_grids(negative_file, {negative});
  EXPECT_THAT(volume_error(negative_file),
              HasSubstr("grid 'density' holds the value -1.000000 at voxel (3, 0, 1); values must be finite and at "
                        "least 0"));

  auto turned = openvdb::FloatGrid::create(0.0f);
  turned->setName("density");
  auto rotation = openvdb::math::Transform::createLinearTransform(0.5);
  rotation->postRotate(0.3, openvdb::math::Z_AXIS);
  turned->setTransform(rotation);
  turned->getAccessor().setValue({0, 0, 0}, 1.0f);
  const auto turned_file = temp_file("turned.vdb");
  write_grids(turned_file, {turned});
  EXPECT_THAT(volume_error(turned_file), HasSubstr("only scaled and translated grids are read"));

  const auto text = temp_file("text.vdb");
  std::ofstream(text) << "not a grid";
  EXPECT_THAT(volume_error(text), HasSubstr("text.vdb: cannot be read as an OpenVDB file"));
  EXPECT_THAT(volume_error(temp_file("missing.vdb")), HasSubstr("missing.vdb: cannot be read as an OpenVDB file"));
}

// A file cut short would make OpenVDB allocate what its broken lengths
// claim (gigabytes from the first 150 bytes of a grid file): the header is
// checked against the file's size first, whatever the cut.
TEST(VdbVolume, AFileCutShortIsRefusedBeforeOpenVdbReadsIt) {
  const auto whole = ramp_file();
  std::ifstream in(whole, std::ios::binary);
  const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  const auto cut = temp_file("cut.vdb");
  for (const size_t length : {size_t(20), size_t(60), size_t(100), size_t(150), size_t(200), bytes.size() - 1}) {
    std::ofstream(cut, std::ios::binary).write(bytes.data(), std::streamsize(length));
    EXPECT_THAT(volume_error(cut), HasSubstr("cut.vdb: is cut short or corrupt: ")) << length;
  }
  EXPECT_THAT(volume_error(cut), HasSubstr("grid 1 ends at byte " + std::to_string(bytes.size()) + " of a file of " +
                                           std::to_string(bytes.size() - 1) + " bytes"));
}

// Lengths inside a grid that are wrong but within the file: the grid's
// metadata entries and its transform's type name are checked against
// where its topology begins (OpenVDB would allocate what they claim).
// Each length is found by the string it prefixes.
TEST(VdbVolume, WrongLengthsInsideAGridAreRefusedByName) {
  const auto whole = ramp_file();
  std::ifstream in(whole, std::ios::binary);
  const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  const auto bad = temp_file("corrupt.vdb");
  const auto corrupted = [&](size_t at, uint32_t length = 0x7ffffff0u) {
    std::string copy = bytes;
    std::memcpy(&copy[at], &length, sizeof length);
    std::ofstream(bad, std::ios::binary).write(copy.data(), std::streamsize(copy.size()));
    return volume_error(bad);
  };
  // The grid's own metadata ("file_bbox_max" is one of OpenVDB's entries).
  const size_t entry = bytes.find("file_bbox_max");
  ASSERT_NE(entry, std::string::npos);
  EXPECT_THAT(corrupted(entry - 4), HasSubstr("corrupt.vdb: is cut short or corrupt: grid 1's metadata entry "));
  EXPECT_THAT(corrupted(entry - 4), HasSubstr(" claims more bytes than the file holds"));
  // A length that ends 50 bytes before the file does: within the file, but
  // past where the grid's leaf data begins (its last 414 bytes here).
  EXPECT_THAT(corrupted(entry - 4, uint32_t(bytes.size() - entry - 50)),
              HasSubstr("runs to byte " + std::to_string(bytes.size() - 50) + ", past the grid's data at byte "));
  const size_t map = bytes.find("UniformScaleTranslateMap");
  ASSERT_NE(map, std::string::npos);
  EXPECT_THAT(corrupted(map - 4),
              HasSubstr("corrupt.vdb: is cut short or corrupt: grid 1's transform type claims more bytes than the "
                        "file holds"));
}

#else

TEST(VdbVolume, ABuildWithoutOpenVdbSaysSo) {
  EXPECT_FALSE(reads_vdb_files());
  const auto file = temp_file("any.vdb");
  std::ofstream(file) << "x";
  EXPECT_THAT(volume_error(file), HasSubstr("any.vdb: this build of caustica reads no OpenVDB files"));
}

#endif

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
