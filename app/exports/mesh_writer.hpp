#pragma once

// Surface meshes out: binary STL and binary PLY, in patient coordinates (LPS millimetres).
#include "core/surface_mesh.hpp"

#include <filesystem>
#include <optional>

namespace steerseg::exports {

enum class MeshFormat { Stl, Ply };

// By the file's extension, case-insensitive: .stl or .ply; nullopt for any other.
std::optional<MeshFormat> meshFormatFor(const std::filesystem::path& path);

// Binary STL: the 80-byte header says "steerseg surface, LPS mm" (STL has no other place for
// it), one facet per triangle with its outward unit normal, coordinates as float32.
void writeStl(const std::filesystem::path& path, const SurfaceMesh& mesh);

// Binary little-endian PLY, indexed (shared vertices, float32 x y z; faces as lists of int),
// with comment lines naming the LPS convention and the millimetre unit.
void writePly(const std::filesystem::path& path, const SurfaceMesh& mesh);

// writeStl or writePly as `format` says.
void writeMesh(const std::filesystem::path& path, const SurfaceMesh& mesh, MeshFormat format);

// Every writer goes through a temporary file beside `path` and a rename, so a crash never
// leaves a half-written mesh under the final name. An empty mesh (nothing inside the
// segmentation) is refused rather than written as a file of no triangles, which viewers show
// as nothing at all or reject. Throws files::WriteError naming the path and the reason.

} // namespace steerseg::exports
