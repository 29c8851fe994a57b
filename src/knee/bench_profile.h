#pragma once
// Cylinder bench displacement profiles (Chien 2014, Methods): a walking knee-angle curve,
// time- and amplitude-scaled to a speed, modified to enter hyperextension at the end of
// stance extension, held there for a few samples, converted to piston position with Eq. 1
// and sampled at the bench rate for several cycles. docs/mauch.md states every choice.
#include <string>
#include <vector>

#include "core/units.h"
#include "knee/knee_geometry.h"

namespace swingsim {

/// One stride of knee flexion from heel strike to the next heel strike, uniformly sampled
/// (the last sample is the one before the next heel strike).
struct KneeAngleStride {
  std::vector<double> flexion;  ///< rad, one value per frame
  std::string source;           ///< file the stride came from, for messages
};

struct BenchProfileParams {
  double strideTime = 0.987;    ///< s, > 0 (Winter natural cadence: 0.987 s)
  double amplitudeScale = 1.0;  ///< knee angles multiplied by this (speed effect), > 0
  /// The curve is shifted so its lowest point (Winter's terminal swing, -3 deg) sits here, rad:
  /// the bench must not latch in terminal swing (the paper: end-swing hyperextension is too
  /// brief to act on the knee).
  double terminalSwingMinimum = 3.0 * kDegToRad;
  /// Stance-extension minimum moved to this angle, rad (< 0: hyperextension).
  double hyperextension = -4.0 * kDegToRad;
  int holdSamples = 4;        ///< samples either side of the minimum held at it
  double sampleRate = 361.4;  ///< Hz
  int cycles = 5;
};

/// A sampled bench profile.
struct BenchProfile {
  std::vector<double> time;      ///< s, from 0 (heel strike)
  std::vector<double> flexion;   ///< knee flexion, rad
  std::vector<double> position;  ///< piston position x, m (Eq. 1)
};

/// Knee flexion (rad) over one stride at stride fraction s in [0, 1), after amplitude
/// scaling, offset and the hyperextension modification (no hold: that acts on samples).
/// Periodic Catmull-Rom interpolation of the stride's frames.
double calcModifiedFlexion(const KneeAngleStride& stride, const BenchProfileParams& p, double s);

/// Builds the sampled profile. Throws std::invalid_argument on bad parameters.
BenchProfile makeBenchProfile(const KneeAngleStride& stride, const BenchProfileParams& p, const KneeGeometry& geometry);

}  // namespace swingsim
