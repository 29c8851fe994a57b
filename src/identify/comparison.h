#pragma once
// Model vs measurement, the same for every plant: per record the measured and predicted
// quantity (cylinder force in N, knee flexion in deg), the residual, the phase of every sample
// and the error metrics overall and per phase; plus the variables the residual is binned
// against to see where in the state space it sits.
#include <string>
#include <vector>

#include "numerics/metrics.h"

namespace swingsim {

/// A state variable the residual is binned against (piston velocity, knee flexion, ...).
struct StateVariable {
  std::string label;           ///< with unit: "piston velocity (mm/s)"
  std::string title;           ///< plot panel title; empty: a generic one
  std::vector<double> values;  ///< one per sample, in the label's unit
};

/// One record run through the model.
struct RecordComparison {
  std::string stem;  ///< record name (file stem)
  bool training = false;
  std::vector<double> time;      ///< s
  std::vector<double> measured;  ///< the compared quantity, in Comparison::unit
  std::vector<double> predicted;
  std::vector<double> residual;  ///< measured - predicted
  std::vector<int> phase;        ///< index into Comparison::phaseNames per sample
  std::vector<StateVariable> variables;
  ErrorMetrics overall;
  std::vector<ErrorMetrics> perPhase;
  std::vector<double> phaseShare;   ///< share of the squared error in each phase (sums to 1)
  std::vector<double> sampleShare;  ///< share of the samples in each phase
  /// A second compared quantity when the plant has one (the swing's hip flexion), else empty.
  ErrorMetrics secondary;
  /// Its measured and model series (Comparison::unit), empty if the plant has none.
  std::vector<double> secondaryMeasured, secondaryPredicted;
};

struct Comparison {
  std::string quantity;           ///< "force", "knee flexion"
  std::string unit;               ///< "N", "deg"
  std::string secondaryQuantity;  ///< "hip flexion", or empty
  std::vector<std::string> phaseNames;
  std::vector<RecordComparison> records;  ///< training records first
  double plotSeconds = 1e300;             ///< span of each record shown against time, s
  int decimals = 1;                       ///< decimals to print errors with (1 for N, 2 for deg)
};

/// A quantity the model applies but is never fitted to, against an independent
/// measurement of it: the swing's knee moment against a knee moment from inverse dynamics
/// (docs/winter.md). Whole records; the fit never sees the measured column.
struct HeldBackComparison {
  std::string quantity;  ///< "knee moment"
  std::string unit;      ///< "N m"
  struct Record {
    std::string stem;
    bool training = true;
    std::vector<double> time, measured, model;
    double rmse = 0, correlation = 0;  ///< correlation: Pearson's r of measured and model
  };
  std::vector<Record> records;
  double rmse = 0, correlation = 0;  ///< over every sample of every record
};

/// Fills each record's and the overall RMSE and correlation.
void finishHeldBackComparison(HeldBackComparison& comparison);

/// Warnings about a finished comparison, each naming the likely cause and the key that fixes
/// it: a record whose measured and model quantities correlate below zero (a sign flipped in
/// reading the measurement: `knee_sign`).
std::vector<std::string> checkHeldBackComparison(const HeldBackComparison& comparison);

/// Fills a record's residual, overall metrics, per-phase metrics and shares from its
/// measured, predicted and phase vectors (`phases` phases).
void finishRecordComparison(RecordComparison& record, std::size_t phases);

/// Where the residual of `comparison`'s training records sits: the phase with the largest
/// excess of squared error over its share of samples, and the state variable whose binned
/// mean residual departs most from zero (bins corrected by `effectiveSampleRatio` = n_eff/n).
std::string describeResidualStructure(const Comparison& comparison, double effectiveSampleRatio);

}  // namespace swingsim
