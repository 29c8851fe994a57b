#include "io/trajectory_writer.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "core/input_error.h"
#include "core/output_files.h"
#include "io/csv_table.h"
#include "io/osim_model.h"
#include "model/leg_parameters.h"

namespace swingsim {

namespace {

std::vector<double> toDegrees(const std::vector<double>& v) {
  std::vector<double> out(v);
  for (double& x : out) x *= kRadToDeg;
  return out;
}

const std::vector<std::string> kColumns = {
    "time_s",        "hip_flexion_deg", "knee_flexion_deg", "hip_flexion_rate_deg_s", "knee_flexion_rate_deg_s",
    "hip_moment_Nm", "knee_moment_Nm"};

std::vector<std::vector<double>> columnsOf(const SwingTrajectory& t) {
  return {t.time,
          toDegrees(t.hipFlexion),
          toDegrees(t.kneeFlexion),
          toDegrees(t.hipFlexionRate),
          toDegrees(t.kneeFlexionRate),
          t.hipMoment,
          t.kneeMoment};
}

}  // namespace

TrajectoryColumns calcTrajectoryColumns(const SwingTrajectory& trajectory) { return {kColumns, columnsOf(trajectory)}; }

std::string formatTrajectoryCsv(const SwingTrajectory& trajectory) {
  return formatCsv(kColumns, columnsOf(trajectory));
}

std::vector<std::string> calcTrajectoryStoLabels(char side) {
  const std::string hip = makeOsimHipCoordinate(side), knee = makeOsimKneeCoordinate(side);
  return {"time", hip, knee, hip + "_speed", knee + "_speed", hip + "_moment", knee + "_moment"};
}

std::string formatTrajectorySto(const SwingTrajectory& trajectory, const std::string& name, char side) {
  if (side != 'r' && side != 'l')
    throw std::invalid_argument(std::string("formatTrajectorySto: side: expected r or l (got ") + side + ")");
  std::string out = name + "\nversion=1\nnRows=" + std::to_string(trajectory.size()) +
                    "\nnColumns=" + std::to_string(kColumns.size()) + "\ninDegrees=yes\nendheader\n";
  // OpenSim names: 'time' first, tab-separated; the knee's angle, rate and moment in the
  // sign of knee_angle_<side> (negative in flexion), as the exported model and a lab's files.
  std::vector<std::vector<double>> columns = columnsOf(trajectory);
  for (std::size_t k : {std::size_t{2}, std::size_t{4}, std::size_t{6}})
    for (double& x : columns[k]) x = -x + 0.0;  // (+ 0.0: no -0)
  std::string csv = formatCsv(calcTrajectoryStoLabels(side), columns);
  for (char& c : csv)
    if (c == ',') c = '\t';
  return out + csv;
}

std::string makeTrajectoryFileStem(const std::string& participantName, double lowering) {
  // Whole millimetres as lower050mm; any other lowering in full, so two lowerings never
  // share a file (0.4 mm is lower0.4mm, not lower000mm).
  const double mm = lowering * 1000;
  char tag[64];
  if (std::fabs(mm - std::round(mm)) < 1e-9 && mm < 1e6)
    std::snprintf(tag, sizeof tag, "lower%03.0fmm", mm);
  else
    std::snprintf(tag, sizeof tag, "lower%smm", formatNumber(mm).c_str());
  return makeSafeFileStem(participantName) + "-" + tag;
}

std::string makeTrajectoryFolder(const std::string& participantName) {
  return "out/simulate-" + makeSafeFileStem(participantName);
}

}  // namespace swingsim
