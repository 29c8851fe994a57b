#include "report/overlay_plot.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "hidden_damper_comparison.h"
#include "identify/swing_plant.h"
#include "identify/synthetic_swing.h"
#include "io/knee_model_loader.h"
#include "io/participant_loader.h"
#include "report/svg_plot.h"

namespace swingsim {
namespace {

namespace fs = std::filesystem;

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto p = text.find(what); p != std::string::npos; p = text.find(what, p + what.size())) ++n;
  return n;
}

std::string readText(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// A swing with a hidden damper compared with the plain model, and a knee moment record with
// the same stem: the figure has three panels (knee, hip, knee moment), each with the measured
// series (black) and the model's (palette colour 1).
TEST(OverlayPlot, WritesMeasuredAndModelForKneeHipAndKneeMoment) {
  // Data with a hidden viscous damper, compared with the plain model: a structured residual.
  const Comparison cmp = testing::compareHiddenDamperSwing();
  ASSERT_EQ(cmp.records.size(), 1u);
  const RecordComparison& r = cmp.records[0];
  ASSERT_EQ(r.secondaryMeasured.size(), r.time.size());

  HeldBackComparison moment;
  moment.quantity = "knee moment";
  moment.unit = "N m";
  moment.records.push_back({"normal", true, {0.0, 0.1, 0.2}, {1.0, -2.0, 0.5}, {0.8, -1.5, 0.2}});
  finishHeldBackComparison(moment);

  const fs::path dir = fs::temp_directory_path() / ("swingsim-overlay-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  const auto paths = writeOverlayPlots(dir.string(), "compare", cmp, &moment);
  ASSERT_EQ(paths.size(), 1u);
  EXPECT_EQ(fs::path(paths[0]).filename(), "compare-normal-overlay.svg");
  const std::string svg = readText(paths[0]);
  fs::remove_all(dir);
  EXPECT_NE(svg.find("knee flexion: measured and model"), std::string::npos);
  EXPECT_NE(svg.find("hip flexion: measured and model"), std::string::npos);
  EXPECT_NE(svg.find("knee moment: model against inverse dynamics"), std::string::npos);
  EXPECT_NE(svg.find("measured (inverse dynamics)"), std::string::npos);
  // Three measured lines and three model lines, one of each per panel.
  EXPECT_EQ(count(svg, "stroke=\"#000000\" stroke-width=\"2.0\""), 3u);
  EXPECT_EQ(count(svg, "stroke=\"" + svgPaletteColor(1) + "\" stroke-width=\"1.5\""), 3u);

  // Without a knee moment: two panels; a plant without a second quantity (the bench): no figure.
  const std::string noMoment = renderOverlaySvg(r, cmp, nullptr, "", "t");
  EXPECT_EQ(noMoment.find("knee moment"), std::string::npos);
  EXPECT_EQ(count(noMoment, "stroke=\"#000000\" stroke-width=\"2.0\""), 2u);
  Comparison bench = cmp;
  bench.secondaryQuantity.clear();
  EXPECT_TRUE(writeOverlayPlots(dir.string(), "compare", bench).empty());
}

}  // namespace
}  // namespace swingsim
