#pragma once
// Published swing times of Burkett, Smeathers & Barker (2004): Table 3 (standard knee-axis
// location) and Table 4 (lowered knee axis), and the model's predicted optimum lowering.
// Table 3's model predictions are the calibration targets. Table 4 is the validation set of
// the sweep, and no default of the sweep is tuned to it; in the sweep diagnosis
// (studies/burkett2004-table4.yaml, identify/sweep_plant.h) its measured column is the
// measurement, and every number fitted to it there is reported as fitted.
#include <string>
#include <vector>

namespace swingsim {

struct PublishedSwingRow {
  double lowering;            ///< m below the standard location
  double measuredProsthetic;  ///< s, mean of 5 trials
  double model;               ///< s, Burkett's model prediction
  double measuredAnatomical;  ///< s
};

struct PublishedParticipant {
  std::string name;              ///< "P1".."P4"
  double table3Model;            ///< s, Table 3 model prediction (calibration target)
  double table3Measured;         ///< s, Table 3 measured mean
  double table3MeasuredSd;       ///< s
  double predictedBestLowering;  ///< m, the paper's model optimum
  std::vector<PublishedSwingRow> table4;
};

/// The four participants of the paper; nullptr if `name` is not one of them.
const PublishedParticipant* findPublished(const std::string& name);
const std::vector<PublishedParticipant>& publishedParticipants();

}  // namespace swingsim
