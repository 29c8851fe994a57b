#include "io/trajectory_writer.h"

#include "io/csv_table.h"
#include "model/leg_parameters.h"

namespace swingsim {

namespace {

std::vector<double> toDegrees(const std::vector<double>& v) {
  std::vector<double> out(v);
  for (double& x : out) x *= kRadToDeg;
  return out;
}

const std::vector<std::string> kColumns = {"time_s", "hip_flexion_deg", "knee_flexion_deg",
                                           "hip_flexion_rate_deg_s", "knee_flexion_rate_deg_s",
                                           "hip_moment_Nm", "knee_moment_Nm"};

std::vector<std::vector<double>> columnsOf(const SwingTrajectory& t) {
  return {t.time, toDegrees(t.hipFlexion), toDegrees(t.kneeFlexion), toDegrees(t.hipFlexionRate),
          toDegrees(t.kneeFlexionRate), t.hipMoment, t.kneeMoment};
}

}  // namespace

TrajectoryColumns calcTrajectoryColumns(const SwingTrajectory& trajectory) {
  return {kColumns, columnsOf(trajectory)};
}

std::string formatTrajectoryCsv(const SwingTrajectory& trajectory) {
  return formatCsv(kColumns, columnsOf(trajectory));
}

std::string formatTrajectorySto(const SwingTrajectory& trajectory, const std::string& name) {
  std::string out = name + "\nversion=1\nnRows=" + std::to_string(trajectory.size()) +
                    "\nnColumns=" + std::to_string(kColumns.size()) + "\ninDegrees=yes\nendheader\n";
  // OpenSim names: 'time' first, tab-separated.
  std::string csv = formatCsv({"time", "hip_flexion", "knee_flexion", "hip_flexion_speed", "knee_flexion_speed",
                               "hip_moment", "knee_moment"},
                              columnsOf(trajectory));
  for (char& c : csv) if (c == ',') c = '\t';
  return out + csv;
}

}  // namespace swingsim
