// Directed triangle suites for test-vector packages (`rastersim vectors --suite NAME`), placed
// relative to the profile's screen so that every profile gets valid triangles (inside the guard band).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "model/profile.h"
#include "model/triangle.h"

namespace rastersim::vectors {

// Name and one-line description of every suite.
std::vector<std::pair<std::string, std::string>> suite_list();

// The triangles of suite `name` for the profile; throws std::invalid_argument for an unknown name.
std::vector<SnappedTriangle> suite_triangles(const std::string& name, const Profile& profile);

}  // namespace rastersim::vectors
