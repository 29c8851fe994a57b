#include "report/sweep_html.h"

#include <stdexcept>

#include "core/text_format.h"
#include "report/markdown_html.h"
#include "report/stick_figure_animation.h"
#include "report/sweep_report_parts.h"

namespace swingsim {

using namespace sweep_report_parts;

namespace {

// Plain, print-friendly styling; the figures keep their own sizes up to the page width.
const char* const kStyle =
    "body{font-family:sans-serif;max-width:1000px;margin:2em auto;padding:0 1em;line-height:1.45;color:#222}"
    "table{border-collapse:collapse;margin:1em 0;font-size:0.9em}"
    "th,td{border:1px solid #ccc;padding:0.25em 0.5em;text-align:left}th{background:#f2f2f2}"
    "pre{background:#f6f6f6;padding:0.6em;overflow-x:auto;font-size:0.85em}"
    "figure{margin:1em 0}figure svg{max-width:100%;height:auto}figcaption{font-size:0.9em;color:#444}";

// Replaces every `from` in `text` with `to`.
std::string replaceAll(std::string text, const std::string& from, const std::string& to) {
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

// A figure file inline: its ids (the plots' clip paths, the same in every figure) prefixed
// so that the figures of one page do not take each other's.
std::string inlineSvg(const std::string& svg, const std::string& idPrefix) {
  return replaceAll(replaceAll(svg, "id=\"", "id=\"" + idPrefix), "url(#", "url(#" + idPrefix);
}

// The participant's fastest swing, animated with its caption; "" if it has none to show.
std::string formatFastestSwingFigure(const SweepStudy& study, const ParticipantSweep& ps) {
  const Participant* p = participantNamed(study, ps.name);
  if (p == nullptr || ps.best < 0) return "";
  const SweepPoint& b = ps.points[static_cast<std::size_t>(ps.best)];
  if (!b.ok || b.result.trajectory.size() == 0) return "";
  return "<figure class=\"fastest-swing\">\n" + renderStickFigureAnimation(b.result, calcHipHeight(*p)) +
         "<figcaption>" + escapeHtml(ps.name) + ", fastest swing: knee axis lowered " + fmt("%.3f", b.lowering) +
         " m, swing time " + fmt("%.4f", b.result.swingTime) +
         " s (toe-off to swing end in real time, the last pose held " + fmt("%.1f", kStickFigureHold) +
         " s, looping; hip fixed, ground dashed, toe path grey)</figcaption>\n</figure>\n";
}

}  // namespace

std::string makeSweepReportHtml(const SweepStudy& study, const SweepResults& results,
                                const std::map<std::string, std::string>& files) {
  int figureCount = 0;
  MarkdownHtmlHooks hooks;
  hooks.image = [&](const std::string& alt, const std::string& path) {
    const auto it = files.find(path);
    if (it == files.end())
      throw std::logic_error("makeSweepReportHtml: report.md links " + path + ", which is not in the report");
    return "<figure>\n" + inlineSvg(it->second, "f" + std::to_string(++figureCount) + "-") + "<figcaption>" +
           escapeHtml(alt) + "</figcaption>\n</figure>\n";
  };
  hooks.afterHeading = [&](int level, const std::string& text) {
    if (level != 2) return std::string();
    for (const auto& ps : results.participants)
      if (ps.name == text) return formatFastestSwingFigure(study, ps);
    return std::string();
  };
  const std::string body = renderMarkdownHtml(files.at("report.md"), hooks);
  return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\"/>\n<title>Knee-axis sweep: " +
         escapeHtml(study.name) + "</title>\n<style>" + kStyle + "</style>\n</head>\n<body>\n" + body +
         "</body>\n</html>\n";
}

}  // namespace swingsim
