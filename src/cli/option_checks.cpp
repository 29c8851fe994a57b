#include "cli/option_checks.h"

#include <cmath>
#include <cstdlib>

#include "core/output_paths.h"

namespace swingsim::cli {

namespace {

// The whole of `text` as a finite number.
std::optional<double> readFinite(const std::string& text) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

}  // namespace

CLI::Validator writableFilePath() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        if (text.empty()) return "";  // main() says "expected a value"
        return findOutputFileProblem(text);
      },
      "");
}

CLI::Validator writableFolderPath() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        if (text.empty()) return "";  // main() says "expected a value"
        return findOutputFolderProblem(text);
      },
      "");
}

CLI::Validator finiteNumber(std::function<std::string(double)> check) {
  return CLI::Validator(
      [check](std::string& text) -> std::string {
        const std::optional<double> v = readFinite(text);
        if (!v) return "expected a number (got '" + text + "')";
        if (!check) return "";
        const std::string bad = check(*v);
        return bad.empty() ? "" : bad + " (got " + text + ")";
      },
      "");
}

CLI::Validator wholeNumberIn(const WholeNumberRange& range) {
  return CLI::Validator(
      [range](std::string& text) -> std::string {
        const std::optional<double> v = readFinite(text);
        if (!v || !range.check(*v).empty()) return range.expected + " (got '" + text + "')";
        text = std::to_string(static_cast<long long>(*v));  // "2.0" -> "2" for CLI11's integer conversion
        return "";
      },
      "");
}

CLI::Validator oneOf(const std::vector<std::string>& keys) {
  return CLI::Validator(
      [keys](std::string& text) -> std::string {
        std::string known;
        for (const auto& k : keys) {
          if (k == text) return "";
          known += (known.empty() ? "" : ", ") + k;
        }
        return "expected one of " + known + " (got '" + text + "')";
      },
      "");
}

std::optional<AddedMass> readAddedMass(const std::string& text) {
  const auto at = text.find('@');
  if (at == std::string::npos) return std::nullopt;
  const std::optional<double> mass = readFinite(text.substr(0, at));
  const std::optional<double> distance = readFinite(text.substr(at + 1));
  if (!mass || !distance || *mass < 0 || *distance < 0) return std::nullopt;
  AddedMass m;
  m.mass = *mass;
  m.distanceBelowKnee = *distance;
  return m;
}

CLI::Validator addedMassSpec() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        return readAddedMass(text) ? "" : "expected KG@METRES below the knee, e.g. 0.5@0.20 (got '" + text + "')";
      },
      "");
}

}  // namespace swingsim::cli
