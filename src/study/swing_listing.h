#pragma once
// The swings of one leg in an OpenSim IK file, as `swingsim swings` and Python's
// swingsim.swings() list them: the request (file, side, force file, gait, knee sign), the
// columns read, the swings found (io/swing_events.h) and their JSON (docs/swing-events.md).
#include <optional>
#include <string>

#include "io/json_file.h"
#include "io/motion_file.h"
#include "io/swing_events.h"

namespace swingsim {

/// What to list; nullopt: not given (the default applies).
struct SwingListRequest {
  std::string kinematics;  ///< OpenSim IK .mot
  std::string side = "r";  ///< "r" or "l"
  std::optional<std::string> grf, verticalForce;
  double thresholdN = 20;  ///< N
  bool fallbackToKinematics = false;
  std::optional<std::string> gait;  ///< "walking" or "running"; nullopt: detected
  double kneeSign = -1;
};

/// The swings found, with what was read to find them.
struct SwingListing {
  MotionColumns columns;
  std::optional<GrfSettings> grf;
  SwingList list;
  double framePeriod = 0;  ///< s between rows of the IK file (0 with fewer than 2 rows)
};

/// OpenSim's example GRF files name the right foot's columns `ground_force_*` and the left
/// foot's `1_ground_force_*`.
std::string defaultVerticalForce(const std::string& side);

/// Reads the IK file (and force file) and lists the complete swings. Throws InputError.
SwingListing listLegSwings(const SwingListRequest& request);

/// The listing as `swingsim swings --json` writes it (disagreements in ms).
Json makeSwingListJson(const SwingListRequest& request, const SwingListing& listing);

}  // namespace swingsim
