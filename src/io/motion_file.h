#pragma once
// OpenSim motion files (.mot, .sto: Storage version 1) and the swing records cut from them.
//   name                     <- optional lines before endheader; `key=value` lines are
//   version=1                   read (version, nRows, nColumns, inDegrees), others ignored
//   nRows=120
//   nColumns=4               <- counts the time column
//   inDegrees=yes            <- yes|no; missing means no (radians), as in OpenSim
//   endheader
//   time  hip_flexion_r  knee_angle_r  hip_moment   <- labels, tab/space separated
//   0.000 12.5 8.1 20.3                             <- numbers, one row per line
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "core/units.h"
#include "model/motion_columns.h"
#include "model/swing_record.h"

namespace swingsim {

/// The numbers of one motion file, as written (angle units as the header says).
struct MotionTable {
  std::string path;
  std::vector<std::string> labels;           ///< column labels, "time" first
  std::vector<std::vector<double>> columns;  ///< one per label, time in s
  std::vector<int> rowLines;                 ///< file line (1-based) of each row
  int labelLine = 0;                         ///< file line of the column labels
  bool inDegrees = false;                    ///< angles in degrees (else radians)
  int inDegreesLine = 0;                     ///< file line of `inDegrees=`; 0 if absent (read as no)

  std::size_t rows() const { return columns.empty() ? 0 : columns.front().size(); }
  /// Index of a column. Throws InputError `path:line: label: column is missing (available: ...)`.
  std::size_t index(const std::string& label) const;
  const std::vector<double>& column(const std::string& label) const { return columns[index(label)]; }
};

/// Most rows a motion file may hold: more is refused before they are all read.
constexpr std::size_t kMaxMotionRows = 2000000;
/// A time step longer than this many times the median step is a gap (missing frames).
constexpr double kMaxStepOverMedian = 5;

/// Reads a motion file, at most 16 MiB (readFile) and kMaxMotionRows rows. Throws
/// InputError `path:line: column: what was expected (got what was found)` for: no
/// `endheader`, a bad `inDegrees`/`nRows`/`nColumns`/`version` value, a first label other
/// than `time`, repeated labels, a row with the wrong number of values, non-numeric,
/// NaN or infinite values, time that does not strictly increase, a gap (a step more than
/// kMaxStepOverMedian times the median step), nRows/nColumns that disagree with the data.
MotionTable readMotionTable(const std::string& path);
/// Same, from text in memory (tests, fuzzers); `path` names it in messages.
MotionTable parseMotionTable(const std::string& text, const std::string& path);

// MotionColumns (which columns make a swing record, and how): model/motion_columns.h.

/// The labels OpenSim's gait models (Gait2354, Gait2392, Gait10dof18musc) give one leg,
/// `side` "r" or "l": hip_flexion_<side>, knee_angle_<side> (knee_sign -1: OpenSim's knee
/// angle is negative in flexion), knee_angle_<side>_moment; pelvis_tilt, pelvis_tx,
/// pelvis_ty when `table` has them.
MotionColumns openSimLegColumns(const MotionTable& table, const std::string& side);
/// The right leg's (a plain .mot named as a participant's thigh_kinematics).
inline MotionColumns openSimRightLegColumns(const MotionTable& table) { return openSimLegColumns(table, "r"); }

/// Default label of the knee moment in an OpenSim inverse-dynamics .sto (right leg).
inline const char* const kOpenSimKneeMoment = "knee_angle_r_moment";

/// Fewest samples a swing record cut from a motion file may have (as the kinematics CSV).
constexpr std::size_t kMinSwingSamples = 10;

/// The swing between toe-off and heel contact, time rebased to 0 at toe-off, angles in rad.
/// Rows strictly inside the cut are kept; toe-off and heel contact are added by linear
/// interpolation when they fall between rows; with a resample interval every sample is
/// linearly interpolated at toe-off + k * interval. Throws InputError for a missing column,
/// a cut outside the file's time or fewer than kMinSwingSamples samples, and for a knee
/// whose range says the unit is wrong (under 3 "deg" with inDegrees=yes: radians; over
/// 6 "rad" with inDegrees=no: degrees), and a knee hyperextended on kHyperextendedShare of
/// the swing's samples (a flipped knee_sign).
/// Pelvis columns, when labelled, fill pelvisX/Y/Tilt; with pelvis tilt the record's hip
/// angle is the thigh's angle in space (hip flexion + pelvis tilt). With `inverseDynamics`
/// (an OpenSim ID .sto), its `columns.kneeMoment` column (default kOpenSimKneeMoment),
/// times kneeSign, is interpolated onto the record's times into kneeMoment: NaN where the
/// .sto does not reach; InputError if it covers none of the swing.
SwingRecord makeSwingRecord(const MotionTable& table, const MotionColumns& columns,
                            const MotionTable* inverseDynamics = nullptr);

/// A knee angle below this is hyperextension no swing reaches: many samples there mean a
/// flipped sign (OpenSim's knee_angle is negative in flexion), rad.
constexpr double kHyperextendedKnee = -5 * kDegToRad;

/// Checks that every column `columns` names (hip, knee, hip_moment, pelvis_*) is in `table`.
/// Throws InputError `<askedBy>.<key>: expected a column of <file> (got '<label>', which it
/// does not have; available: ...)`, `askedBy` naming the file and map that asked for it (e.g.
/// "study.yaml: motion_columns").
void requireNamedColumns(const MotionTable& table, const MotionColumns& columns, const std::string& askedBy);

/// At least this share of knee samples below kHyperextendedKnee is a flipped sign, refused
/// (between half and this a warning): no knee is hyperextended for 90 % of a recording.
constexpr double kHyperextendedShare = 0.9;

/// The leg's columns over the whole file, the checks every command runs on kinematics before
/// taking events or records from them: the knee's range against the header's unit (under 3
/// "deg" with inDegrees=yes: radians; over 6 "rad" with inDegrees=no: degrees), hip and knee
/// angles physically plausible, and the knee's sign (kHyperextendedShare of the samples
/// hyperextended). Throws InputError naming the file, the column and the fix.
void checkLegKinematics(const MotionTable& table, const MotionColumns& columns);

/// Warnings about a record cut from `table` by `columns`, each naming the likely cause and
/// the motion_columns key that fixes it: more than half of the knee samples below
/// kHyperextendedKnee (`knee_sign: -1`); a hip angle read without the pelvis tilt the file
/// has (`pelvis_tilt`).
std::vector<std::string> checkMotionRecord(const SwingRecord& record, const MotionTable& table,
                                           const MotionColumns& columns);

/// True for a path ending in .mot or .sto (any case).
bool isMotionFile(const std::string& path);

/// Reads a swing record, choosing the format by extension (the one place that does):
/// .mot/.sto through readMotionTable and makeSwingRecord with `columns` (required for
/// those: InputError if absent); anything else as the swing kinematics CSV (readSwingRecord).
SwingRecord readSwingRecordFile(const std::string& path, const std::optional<MotionColumns>& columns);

}  // namespace swingsim
