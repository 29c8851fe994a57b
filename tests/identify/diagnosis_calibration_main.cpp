// diagnosis_calibration: the calibration study of the diagnosis, one table (docs/diagnosis.md,
// "How far the intervals can be trusted"). Run by scripts/diagnosis-calibration.sh.
// Usage: diagnosis_calibration [--seeds N] [--first S] [--jobs J] [--only SUBSTRING[,SUBSTRING...]] --out DIR
//        diagnosis_calibration --sweep-effect-sizes   (how far each hidden sweep effect moves the
//        truth's swing times, noise free, against a row's noise: a table on stdout)
// Writes DIR/calibration.md (the table) and DIR/calibration.csv (one row a case) and
// DIR/calibration-seeds.csv (one row a seed).
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include "diagnosis_calibration.h"

namespace {

using namespace swingsim::calibration;

struct Options {
  int seeds = 20, jobs = 1;
  std::uint64_t first = 1;
  std::string only, out;
  bool sweepEffectSizes = false;
};

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--sweep-effect-sizes") {
      o.sweepEffectSizes = true;
      continue;
    }
    if (i + 1 >= argc) throw std::invalid_argument("option " + a + " needs a value");
    const std::string v = argv[++i];
    if (a == "--seeds")
      o.seeds = std::stoi(v);
    else if (a == "--jobs")
      o.jobs = std::stoi(v);
    else if (a == "--first")
      o.first = std::stoull(v);
    else if (a == "--only")
      o.only = v;
    else if (a == "--out")
      o.out = v;
    else
      throw std::invalid_argument("unknown option " + a);
  }
  if (o.sweepEffectSizes) return o;
  if (o.out.empty() || o.seeds < 1 || o.jobs < 1)
    throw std::invalid_argument(
        "usage: diagnosis_calibration [--seeds N>=1] [--first S] [--jobs J>=1] [--only SUBSTRING[,SUBSTRING...]] --out "
        "DIR");
  return o;
}

std::string num(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.4g", v);
  return b;
}

// Whether `name` contains one of the comma-separated substrings of `only` ("" selects all).
bool selected(const std::string& only, const std::string& name) {
  if (only.empty()) return true;
  std::stringstream list(only);
  for (std::string part; std::getline(list, part, ',');)
    if (!part.empty() && name.find(part) != std::string::npos) return true;
  return false;
}

std::string caseName(const CalibrationCase& c) { return c.effect.empty() ? "null" : c.effect; }

// One markdown row: named, other, coverage, bias and spread (with the bias in % of the truth).
std::string markdownRow(const CalibrationCase& c, const CaseSummary& s) {
  std::string row = "| " + c.plant + " | " + caseName(c) + " | " + c.size + " | " + std::to_string(s.seeds) + " | ";
  // Before the near-miss rules (SeedOutcome::beforeNamedFirst), from the same fits.
  const std::string before = " (before " + std::to_string(s.beforeNamed) + ")";
  const std::string otherBefore = " (before " + std::to_string(s.beforeOther) + ")";
  row += c.effect.empty() || isOutsideLibrary(c)
             ? "- | " + std::to_string(s.other) + " false" + otherBefore + " | "
             : std::to_string(s.named) + before + " | " + std::to_string(s.other) + otherBefore + " | ";
  if (c.parameter.empty() || s.scored == 0) return row + "- | - | - | - |";
  row += c.parameter + " | " + std::to_string(s.covered) + "/" + std::to_string(s.scored);
  if (s.oneSided > 0) row += " (" + std::to_string(s.oneSided) + " not Wald)";
  row += " | " + num(s.bias) + " (" + num(100.0 * s.bias / c.truth) + " %) | " + num(s.sd) + " |";
  return row;
}

// The sweep cases' effect sizes in swing time (calcSweepEffectSize), one markdown row each.
void printSweepEffectSizes() {
  std::cout << "| hidden effect | size | rows | RMS change ms | after each participant's mean ms | row noise ms |\n"
            << "|---|---|---|---|---|---|\n";
  for (const auto& h : sweepHiddenEffects()) {
    if (h.effect.empty()) continue;
    const SweepEffectSize e = calcSweepEffectSize(h);
    std::cout << "| " << h.effect << " | " << h.size << " | " << e.rows << " | " << num(1e3 * e.rawRmsS) << " | "
              << num(1e3 * e.shapeRmsS) << " | " << num(1e3 * e.rowNoiseS) << " |\n";
  }
}

}  // namespace

int main(int argc, char** argv) try {
  const Options o = parse(argc, argv);
  if (o.sweepEffectSizes) {
    printSweepEffectSizes();
    return 0;
  }
  std::filesystem::create_directories(o.out);
  std::ofstream md(o.out + "/calibration.md"), csv(o.out + "/calibration.csv"), seeds(o.out + "/calibration-seeds.csv");
  md << "| plant | hidden effect | size | seeds | named first | other named | parameter | 95 % CI holds truth | bias "
        "(mean - truth) | SD |\n"
     << "|---|---|---|---|---|---|---|---|---|---|\n";
  csv << "plant,effect,size,truth,parameter,seeds,named,other_named,scored,covered,not_wald,bias,sd,seconds,"
         "named_before,other_named_before\n";
  seeds << "plant,effect,seed,named_first,other_named,estimate,lower,upper,note,"
           "first_lr,first_p_adjusted,first_significant,first_bic,first_validation,first_physical,final_parameters,"
           "first_all_rows_p,first_fold_p,best_all_rows_p_adjusted,best_all_rows\n";
  const auto start = std::chrono::steady_clock::now();
  for (const auto& c : calibrationCases()) {
    if (!selected(o.only, c.plant + "/" + caseName(c))) continue;
    const auto t0 = std::chrono::steady_clock::now();
    const auto outcomes = runCase(c, o.first, o.seeds, o.jobs);
    const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const CaseSummary s = summarize(c, outcomes);
    md << markdownRow(c, s) << "\n";
    md.flush();
    csv << c.plant << "," << caseName(c) << ",\"" << c.size << "\"," << c.truth << "," << c.parameter << "," << s.seeds
        << "," << s.named << "," << s.other << "," << s.scored << "," << s.covered << "," << s.oneSided << "," << s.bias
        << "," << s.sd << "," << secs << "," << s.beforeNamed << "," << s.beforeOther << "\n";
    csv.flush();
    for (std::size_t i = 0; i < outcomes.size(); ++i) {
      const auto& r = outcomes[i];
      seeds << c.plant << "," << caseName(c) << "," << o.first + i << "," << r.namedFirst << "," << r.otherNamed << ","
            << r.estimate << "," << r.lower << "," << r.upper << ",\"" << r.intervalNote << "\"," << r.firstLr << ","
            << r.firstPAdjusted << "," << r.firstSignificant << "," << r.firstBic << "," << r.firstValidation << ","
            << r.firstPhysical << ",\"" << r.finalParameters << "\"," << r.firstAllRowsP << ",\"" << r.firstFoldP
            << "\"," << r.firstBestAllRowsPAdjusted << "," << r.firstBestAllRows << "\n";
    }
    seeds.flush();
    std::cerr << c.plant << "/" << caseName(c) << ": " << secs << " s\n";
  }
  const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  md << "\n" << o.seeds << " seeds from " << o.first << ", " << o.jobs << " jobs, " << num(total) << " s wall\n";
  std::cout << "wrote " << o.out << "/calibration.md, calibration.csv, calibration-seeds.csv (" << num(total)
            << " s)\n";
  return 0;
} catch (const std::exception& e) {
  std::cerr << "diagnosis_calibration: " << e.what() << "\n";
  return 1;
}
