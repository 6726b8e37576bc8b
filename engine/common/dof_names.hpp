#pragma once
// The names of the rigid body's six degrees of freedom in the order of every
// 6-vector (DESIGN.md conventions: q = [surge, sway, heave, roll, pitch, yaw]).

#include <array>

namespace spiral::engine {

inline constexpr std::array<const char*, 6> kDofNames = {"surge", "sway", "heave", "roll", "pitch", "yaw"};

}  // namespace spiral::engine
