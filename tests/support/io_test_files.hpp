#pragma once

// Small independent writers for the reader tests: scan files of every non-DICOM format built
// from a known volume, so a test can read them back and compare. They share nothing with the
// readers beyond zlib, so a reader bug is not mirrored by the writer.
#include "core/volume.hpp"

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace steerseg::test {

// A rotated, partly flipped, non-isotropic grid away from the origin (LPS).
Geometry obliqueGeometry(const glm::ivec3& dims);

// Voxel (i,j,k) holds pattern(i,j,k) = (i + 3j + 7k) % 251: distinct, fits every type.
double pattern(int i, int j, int k);

// `values` (voxel count) as little- or big-endian bytes of `type`: "uint8", "int8", "int16",
// "uint16", "int32", "uint32", "float32", "float64".
std::vector<std::byte> encodeSamples(const std::vector<double>& values, const std::string& type,
                                     bool bigEndian = false);

// pattern() over a grid, as doubles, i fastest.
std::vector<double> patternValues(const glm::ivec3& dims);

void writeFile(const std::filesystem::path& path, const std::vector<std::byte>& bytes);
void writeFile(const std::filesystem::path& path, const std::string& text);
std::vector<std::byte> concat(const std::string& text, const std::vector<std::byte>& bytes);

struct NiftiOptions {
    int version = 1;
    int datatype = 2; // NIFTI_TYPE_*
    bool bigEndian = false;
    int sformCode = 1;
    int qformCode = 1;
    double slope = 0.0;
    double inter = 0.0;
    int volumes = 1; // dim[4]
};

// A .nii image: header (geometry in RAS, as NIfTI stores it), 4 extension bytes, then `data`.
std::vector<std::byte> niftiFile(const Geometry& g, const std::vector<std::byte>& data,
                                 const NiftiOptions& options = {});

// A FreeSurfer .mgh image (big-endian; type 0 uchar, 1 int, 3 float, 4 short).
std::vector<std::byte> mghFile(const Geometry& g, int type, const std::vector<double>& values);

// Geometry comparison with a tolerance suited to float headers.
void expectSameGeometry(const Geometry& a, const Geometry& b, double tolerance = 1e-4);

// The world-space centre of the voxels whose value is above `threshold`.
glm::dvec3 worldCentroid(const Volume& v, double threshold = 0.5);

} // namespace steerseg::test
