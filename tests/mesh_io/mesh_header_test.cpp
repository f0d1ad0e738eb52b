// The header checks on bytes in memory: counts that cannot fit the file are refused with
// an exact message; headers that fit (and formats without counts) pass.
#include "mesh_io/mesh_header.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>

namespace mhd {
namespace {

const std::string kHugeBinaryPly =
    "ply\nformat binary_little_endian 1.0\nelement vertex 100000000\nproperty float x\nproperty float y\n"
    "property float z\nelement face 100000000\nproperty list uchar int vertex_indices\nend_header\n";

std::string binary_stl(std::uint32_t claimed, std::size_t triangles, std::string_view start = "binary") {
  std::string bytes(80, ' ');
  bytes.replace(0, start.size(), start);
  for (int i = 0; i < 4; ++i) bytes.push_back(static_cast<char>((claimed >> (8 * i)) & 0xffu));
  bytes.append(triangles * 50, '\x01');
  return bytes;
}

MeshHeaderCheck check(const std::string& bytes, std::string_view extension) {
  return check_mesh_header(std::string_view(bytes).substr(0, kMeshHeaderBytes), bytes.size(), extension);
}

// The kind before assimp: zeros named .ply or .obj are refused from their first bytes.
// The dual: a text OBJ and a real PLY header pass.
TEST(MeshHeader, ZerosNamedPlyOrObjAreRefusedByKind) {
  const std::string zeros(1 << 20, '\0');
  EXPECT_EQ(check(zeros, ".ply").error(), "not a PLY file: it does not start with 'ply'");
  EXPECT_EQ(check(zeros, ".PLY").error(), "not a PLY file: it does not start with 'ply'");
  EXPECT_EQ(check(zeros, ".obj").error(), "not an OBJ file: byte 0 is a NUL, and an OBJ is text");
  EXPECT_TRUE(check("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", ".obj").ok());
}

TEST(MeshHeader, BinaryPlyCountsMustFitTheFile) {
  const MeshHeaderCheck c = check(kHugeBinaryPly, ".ply");
  EXPECT_EQ(c.error(),
            "PLY header claims 100000000 vertex and 100000000 face elements, at least 1300000000 bytes of binary "
            "data, but only 0 bytes follow the header");
}

TEST(MeshHeader, AsciiPlyNeedsAboutTwoBytesPerNumber) {
  const std::string ply =
      "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 2\nproperty list uchar int vertex_indices\nend_header\n";
  // 4 vertices * 3 numbers * 2 bytes + 2 faces * 1 list * 2 bytes = 28 bytes at least.
  EXPECT_EQ(check(ply + std::string(27, ' '), ".ply").error(),
            "PLY header claims 4 vertex and 2 face elements, at least 28 bytes of ASCII data, but only 27 bytes "
            "follow the header");
  const MeshHeaderCheck fits = check(ply + "0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2\n3 1 3 2\n", ".ply");
  EXPECT_TRUE(fits.ok()) << fits.error_text();
  EXPECT_EQ(fits->claimed_faces, 2u);
}

TEST(MeshHeader, PlyCountsThatOverflowAreRefused) {
  const std::string ply =
      "ply\r\nformat binary_big_endian 1.0\r\nelement vertex 18446744073709551615\r\nproperty double x\r\n"
      "property double y\r\nproperty double z\r\nend_header\r\n";
  EXPECT_EQ(check(ply, ".ply").error(),
            "PLY header claims 18446744073709551615 vertex elements, at least 2^64 bytes of binary data, but only 0 "
            "bytes follow the header");
  EXPECT_EQ(check("ply\nformat ascii 1.0\nelement vertex 1e8\nend_header\n", ".ply").error(),
            "PLY header: invalid count '1e8' for element 'vertex'");
  EXPECT_EQ(check("ply\nformat ascii 1.0\nelement vertex 99999999999999999999\nend_header\n", ".ply").error(),
            "PLY header: invalid count '99999999999999999999' for element 'vertex'");
}

TEST(MeshHeader, PlyWithoutEndHeaderIsRefused) {
  EXPECT_EQ(check("ply\nformat ascii 1.0\nelement vertex 1\n", ".ply").error(), "PLY header: no end_header");
  std::string endless = "ply\nformat ascii 1.0\n";
  while (endless.size() < 2 * kMeshHeaderBytes) endless += "comment padding padding padding\n";
  EXPECT_EQ(check(endless, ".ply").error(), "PLY header: no end_header in the first 65536 bytes");
  EXPECT_EQ(check("ply\nformat utf16 1.0\nend_header\n", ".ply").error(), "PLY header: unknown format 'utf16'");
}

TEST(MeshHeader, MalformedPlyPropertiesAreRefused) {
  // assimp 5.2 aborts on some of these (found by mhd-fuzz-mesh-header).
  const std::string start = "ply\nformat binary_little_endian 1.0\nelement vertex 1\n";
  EXPECT_EQ(check(start + "property float x\nproperty float\n y\nproperty float z\nend_header\n", ".ply").error(),
            "PLY header: malformed property line 'property float'");
  EXPECT_EQ(check(start + "property float x\nproperty float y\nproperty list uchar z\nend_header\n", ".ply").error(),
            "PLY header: malformed property line 'property list uchar z'");
  EXPECT_EQ(check(start + "property float x\nproperty float y\nproperty quad z\nend_header\n", ".ply").error(),
            "PLY header: malformed property line 'property quad z'");
  EXPECT_EQ(check("ply\nformat ascii 1.0\nproperty float x\nend_header\n", ".ply").error(),
            "PLY header: malformed property line 'property float x'");
  EXPECT_EQ(check(start + "property float x\nproperty float y\nend_header\n" + std::string(8, '\0'), ".ply").error(),
            "PLY header: element 'vertex' has no property 'z'");
}

TEST(MeshHeader, BinaryStlMustBeExactlyAsLongAsItsCount) {
  const MeshHeaderCheck exact = check(binary_stl(3, 3), ".stl");
  EXPECT_TRUE(exact.ok()) << exact.error_text();
  EXPECT_EQ(exact->claimed_faces, 3u);
  EXPECT_EQ(check(binary_stl(1000000, 2), ".STL").error(),
            "binary STL header claims 1000000 triangles (50000084 bytes), but the file has 184 bytes");
  EXPECT_EQ(check(binary_stl(1, 2), ".stl").error(),
            "binary STL header claims 1 triangle (134 bytes), but the file has 184 bytes");
  EXPECT_EQ(check(std::string(40, '\0'), ".stl").error(), "binary STL is 40 bytes, shorter than its 84-byte header");
}

TEST(MeshHeader, BinaryStlStartingWithSolidIsStillBinary) {
  // Many exporters write "solid" into a binary header; the body's control bytes tell.
  std::string lying = binary_stl(4000000000u, 2, "solid part");
  lying[100] = '\0';
  EXPECT_EQ(check(lying, ".stl").error(),
            "binary STL header claims 4000000000 triangles (200000000084 bytes), but the file has 184 bytes");
  const MeshHeaderCheck exact = check(binary_stl(2, 2, "solid part"), ".stl");
  EXPECT_TRUE(exact.ok()) << exact.error_text();
}

TEST(MeshHeader, FormatsWithoutCountsPass) {
  const std::string ascii_stl =
      "solid tri\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertex 1 0 0\n   vertex 0 1 0\n"
      "  endloop\n endfacet\nendsolid tri\n";
  const MeshHeaderCheck stl = check(ascii_stl, ".stl");
  EXPECT_TRUE(stl.ok()) << stl.error_text();
  EXPECT_FALSE(stl->claimed_faces);
  EXPECT_TRUE(check("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", ".obj").ok());
  EXPECT_TRUE(check(std::string(10, '\0'), ".3ds").ok());  // not ours to judge: assimp decides
}

}  // namespace
}  // namespace mhd
