#pragma once
// Physical and angle constants, defined once. Inside the code everything is SI and radians;
// files that people write use degrees where people think in degrees, converted at load.

namespace swingsim {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDegToRad = kPi / 180.0;
constexpr double kRadToDeg = 180.0 / kPi;
constexpr double kGravity = 9.81;  ///< m/s^2, downward

}  // namespace swingsim
