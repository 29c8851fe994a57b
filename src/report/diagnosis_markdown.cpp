#include "report/diagnosis_markdown.h"

#include "core/output_files.h"
#include "report/diagnosis_report.h"
#include "report/missing_plot.h"

namespace swingsim {

std::string formatWarningsSection(const std::vector<std::string>& warnings) {
  if (warnings.empty()) return "";
  std::string md =
      "## Warnings\n\nAbout the data, each naming what fixes it (also on stderr, in the JSON and in Python):\n\n";
  for (const auto& w : warnings) md += "- " + w + "\n";
  return md + "\n";
}

void writeDiagnosisReport(const std::string& outDir, const DiagnosisReportInput& in) {
  const std::string result = formatDiagnosisText(*in.diagnosis, *in.before, *in.after);
  std::string md = "# swingsim diagnose: " + in.studyName + "\n\nCommand: `" + in.command + "`\n\n" +
                   (in.drive.empty() ? "" : "The model's " + in.drive + ".\n\n") +
                   formatWarningsSection(in.diagnosis->warnings) + "## Before\n\n```\n" +
                   formatComparisonTable(*in.before) + "```\n\n## Ranking and result\n\n```\n" + result +
                   (in.check.empty() ? "" : in.check + "\n") + "```\n\n## After\n\n```\n" +
                   formatComparisonTable(*in.after) + "```\n\n## Residual plots\n\n";
  if (in.heldBefore && in.heldAfter) {
    const HeldBackComparison& b = *in.heldBefore;
    md += "## " + b.quantity + " against the measured one (never fitted)\n\n```\n" +
          formatHeldBackText(b, *in.heldAfter) + "```\n\n![" + b.quantity + "](held-back.svg)\n\n";
    for (const auto& w : in.heldWarnings) md += "Warning: " + w + "\n\n";
    writeFileAtomic(outDir + "/held-back.svg", renderHeldBackSvg(b, *in.heldAfter, b.quantity));
  }
  // Where the moment the model lacks acts, in the measured state (not explained only).
  if (const auto& m = in.diagnosis->missing; m && !m->kneeDeg.empty() && !in.diagnosis->explained) {
    md += "## The missing moment, where it acts\n\n" + in.diagnosis->missingNote +
          "\n\n![missing knee moment over measured knee flexion](missing-moment.svg)\n\n" +
          (m->note.empty() ? "" : "Note: " + m->note + "\n\n");
    writeFileAtomic(outDir + "/missing-moment.svg",
                    renderMissingMomentSvg(*m, "The knee moment the measured swings need minus the model's"));
  } else if (const auto& f = in.diagnosis->missingForce; f && !f->forceN.empty() && !in.diagnosis->explained) {
    md += "## The missing force, where it acts\n\n" + in.diagnosis->missingNote +
          "\n\n(The measured force minus the model's at the measured piston motion, over every record, in 2 mm "
          "position bins; a region departs from zero beyond 3.5 standard errors of the noise.)\n\n"
          "![missing cylinder force over measured piston position](missing-force.svg)\n\n";
    writeFileAtomic(outDir + "/missing-force.svg",
                    renderMissingForceSvg(*f, "The force the measured bench records need minus the model's"));
  }
  for (const auto& p : writeResidualPlots(outDir, "before", *in.before))
    md += "- before: [" + fileStem(p) + "](" + fileStem(p) + ".svg)\n";
  for (const auto& p : writeResidualPlots(outDir, "after", *in.after))
    md += "- after: [" + fileStem(p) + "](" + fileStem(p) + ".svg)\n";
  writeFileAtomic(outDir + "/report.md", md);
}

}  // namespace swingsim
