#pragma once
// Swing kinematics CSV (time_s, hip_flexion_deg, knee_flexion_deg, hip_moment_Nm): read and write.
#include <string>

#include "model/swing_record.h"

namespace swingsim {

/// Reads a kinematics CSV; hip_moment_Nm is required here (the drive). Throws InputError.
SwingRecord readSwingRecord(const std::string& path);
/// CSV text of a record (the generator's output).
std::string formatSwingRecordCsv(const SwingRecord& record);

}  // namespace swingsim
