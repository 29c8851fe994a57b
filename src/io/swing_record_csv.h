#pragma once
// Swing kinematics CSV (time_s, hip_flexion_deg, knee_flexion_deg, hip_moment_Nm): read and write.
#include <string>

#include "model/swing_record.h"

namespace swingsim {

/// Reads a kinematics CSV; hip_moment_Nm and knee_moment_Nm are optional here (a study with
/// `drive: hip_moment` requires the hip moment: docs/formats.md). Throws InputError.
SwingRecord readSwingRecord(const std::string& path);
/// The same from CSV text, `source` naming it in messages (a record built in Python).
SwingRecord parseSwingRecordCsv(const std::string& text, const std::string& source);
/// CSV text of a record (the generator's output).
std::string formatSwingRecordCsv(const SwingRecord& record);

}  // namespace swingsim
