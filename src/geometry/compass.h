#pragma once
// The eight unit steps at multiples of 45 degrees that the vertex searches (refinement's
// relocation, --smooth's compass search) try around a vertex: one table, so both walk alike.

namespace deltri {

inline constexpr double kCompassDiagonal = 0.70710678118654752;  // 1/sqrt(2)
inline constexpr double kCompassDirections[8][2] = {
    {1, 0},  {kCompassDiagonal, kCompassDiagonal},   {0, 1},  {-kCompassDiagonal, kCompassDiagonal},
    {-1, 0}, {-kCompassDiagonal, -kCompassDiagonal}, {0, -1}, {kCompassDiagonal, -kCompassDiagonal}};

}  // namespace deltri
