#pragma once
// Trajectory output: CSV with our column names and an OpenSim .sto (version=1 header with
// nRows, nColumns, inDegrees=yes, endheader) so OpenSim users can open it.
#include <string>
#include <vector>

#include "model/swing_trajectory.h"

namespace swingsim {

/// The CSV's columns in file units (angles in degrees): `names` as formatTrajectoryCsv
/// writes them, `values[i]` the samples of column i.
struct TrajectoryColumns {
  std::vector<std::string> names;
  std::vector<std::vector<double>> values;
};
TrajectoryColumns calcTrajectoryColumns(const SwingTrajectory& trajectory);

/// CSV text: time_s, hip_flexion_deg, knee_flexion_deg, hip_flexion_rate_deg_s,
/// knee_flexion_rate_deg_s, hip_moment_Nm, knee_moment_Nm.
std::string formatTrajectoryCsv(const SwingTrajectory& trajectory);
/// OpenSim storage text (angles in degrees, inDegrees=yes) with the columns
/// calcTrajectoryStoLabels(side): the angles named as the coordinates of the model
/// `export-osim --side` writes and as a lab's IK file names them (hip_flexion_r,
/// knee_angle_r), so OpenSim plays the file on that model; the knee's angle, rate and moment
/// in knee_angle's sign (negative in flexion). `side` 'r' or 'l' (std::invalid_argument else).
/// swingsim reads it back (and the older hip_flexion/knee_flexion files) through
/// io/motion_file.h's openSimLegColumns.
std::string formatTrajectorySto(const SwingTrajectory& trajectory, const std::string& name, char side = 'r');
/// time, hip_flexion_<side>, knee_angle_<side>, the same with _speed (deg/s), hip_flexion_<side>_moment,
/// knee_angle_<side>_moment (N m, as OpenSim's inverse dynamics names them).
std::vector<std::string> calcTrajectoryStoLabels(char side);

/// The file stem of one simulated swing's outputs (and of its exported model):
/// `<participant>-lower050mm` (whole millimetres), else `-lower0.4mm` with the lowering in full.
/// `lowering` in m.
std::string makeTrajectoryFileStem(const std::string& participantName, double lowering);
/// The default folder of one simulated swing's outputs (and of its exported model):
/// `out/simulate-<participant>`.
std::string makeTrajectoryFolder(const std::string& participantName);

}  // namespace swingsim
