// The format readers behind read_mesh (mesh.hpp), private to the hull library.
#pragma once
#include <filesystem>

#include <brash/hull/mesh.hpp>

namespace brash::hull {

// Wavefront OBJ (obj_io.cpp).
Mesh read_obj(const std::filesystem::path& file);

}  // namespace brash::hull
