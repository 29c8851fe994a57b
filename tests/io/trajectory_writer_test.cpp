// The trajectory outputs (io/trajectory_writer.h): the CSV read back by the project's own
// reader gives the samples in degrees; the .sto has OpenSim's header and the export-osim
// coordinate names; file stems keep lowerings apart and names safe.
#include "io/trajectory_writer.h"

#include <gtest/gtest.h>

#include <string>

#include "core/units.h"
#include "io/csv_table.h"

namespace swingsim {
namespace {

constexpr double kWrittenDigits = 1e-9;  // relative: %.10g keeps ten significant digits

SwingTrajectory threeSamples() {
  SwingTrajectory t;
  t.time = {0, 0.01, 0.02};
  t.hipFlexion = {0.1, 0.2, 0.3};
  t.kneeFlexion = {0.9, 1.0, 1.1};
  t.hipFlexionRate = {10, 10, 10};
  t.kneeFlexionRate = {-1, 2, -3};
  t.hipMoment = {30, 20.5, -4};
  t.kneeMoment = {-1.25, 0, 1.5};
  return t;
}

TEST(TrajectoryWriter, CsvReadsBackInDegrees) {
  const SwingTrajectory t = threeSamples();
  CsvSpec spec;
  spec.required = calcTrajectoryColumns(t).names;
  spec.strictlyIncreasing = "time_s";
  const CsvTable table = parseCsv(formatTrajectoryCsv(t), "trajectory.csv", spec);
  ASSERT_EQ(table.rows(), 3u);
  EXPECT_TRUE(table.ignored.empty());
  EXPECT_NEAR(table.column("hip_flexion_deg")[2], 0.3 * kRadToDeg, kWrittenDigits * 0.3 * kRadToDeg);
  EXPECT_NEAR(table.column("knee_flexion_rate_deg_s")[1], 2 * kRadToDeg, kWrittenDigits * 2 * kRadToDeg);
  EXPECT_EQ(table.column("hip_moment_Nm"), (std::vector<double>{30, 20.5, -4}));
  EXPECT_EQ(table.column("knee_moment_Nm"), (std::vector<double>{-1.25, 0, 1.5}));
  const TrajectoryColumns columns = calcTrajectoryColumns(t);
  ASSERT_EQ(columns.values.size(), columns.names.size());
  for (std::size_t i = 0; i < 3; ++i)
    EXPECT_NEAR(columns.values[2][i], table.column("knee_flexion_deg")[i], kWrittenDigits * 100)
        << "the numbers the CSV holds";
}

TEST(TrajectoryWriter, StoHasOpenSimsHeaderAndTheModelsCoordinates) {
  const std::string sto = formatTrajectorySto(threeSamples(), "P1-lower050mm");
  const std::string header =
      "P1-lower050mm\nversion=1\nnRows=3\nnColumns=7\ninDegrees=yes\nendheader\n"
      "time\thip_flexion_r\tknee_angle_r\thip_flexion_r_speed\tknee_angle_r_speed\thip_flexion_r_moment\tknee_angle_r_"
      "moment\n";
  EXPECT_EQ(sto.substr(0, header.size()), header);
  EXPECT_EQ(sto.find(','), std::string::npos) << "tabs only";
  const std::string firstRow = sto.substr(header.size(), sto.find('\n', header.size()) - header.size());
  EXPECT_EQ(firstRow.rfind("0\t5.729577951\t-51.56620156\t572.9577951\t57.29577951\t30\t1.25", 0), 0u)
      << firstRow;  // knee_angle_r: - = flexion
}

TEST(TrajectoryWriter, FileStemsKeepLoweringsApartAndNamesSafe) {
  EXPECT_EQ(makeTrajectoryFileStem("P1", 0.05), "P1-lower050mm");
  EXPECT_EQ(makeTrajectoryFileStem("P1", 0), "P1-lower000mm");
  EXPECT_EQ(makeTrajectoryFileStem("P1", 0.125), "P1-lower125mm");
  EXPECT_EQ(makeTrajectoryFileStem("P1", 0.0004), "P1-lower0.4mm") << "not rounded to lower000mm";
  EXPECT_NE(makeTrajectoryFileStem("P1", 0.0504), makeTrajectoryFileStem("P1", 0.05));
  EXPECT_EQ(makeTrajectoryFileStem("a/b c", 0.05).find('/'), std::string::npos);
  EXPECT_EQ(makeTrajectoryFolder("P1"), "out/simulate-P1");
  EXPECT_EQ(makeTrajectoryFolder("../x").find(".."), std::string::npos) << "a name cannot leave out/";
}

}  // namespace
}  // namespace swingsim
