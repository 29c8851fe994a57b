#include "report/cylinder_fit_report.h"

#include <cmath>
#include <cstdio>

#include "core/output_files.h"
#include "core/text_format.h"
#include "io/json_file.h"
#include "report/svg_plot.h"

namespace swingsim {

namespace {

const char* kPhaseNames4[] = {"1 stance flexion", "2 flexion after hyperextension", "3 extension", "4 hyperextension"};
const char* kPhaseNames2[] = {"1 high force (stance flexion)", "2 low force"};

std::string phaseName(int phases, int i) { return phases == 2 ? kPhaseNames2[i] : kPhaseNames4[i]; }

std::string phaseColor(int i) {
  static const char* c[] = {"#D55E00", "#0072B2", "#009E73", "#CC79A7"};
  return c[i % 4];
}

}  // namespace

std::vector<FileEvaluation> evaluateFiles(const MauchCylinder& cylinder, const std::vector<BenchData>& train,
                                          const std::vector<BenchData>& validate) {
  std::vector<FileEvaluation> out;
  for (int role = 0; role < 2; ++role) {
    for (const auto& d : role == 0 ? train : validate) {
      FileEvaluation e;
      e.data = &d;
      e.training = role == 0;
      e.trace = predictBench(cylinder, d);
      e.metrics = calcErrorMetrics(d.force, e.trace.force);
      out.push_back(std::move(e));
    }
  }
  return out;
}

std::string formatFitTable(const std::vector<ModelEvaluation>& models) {
  std::string s;
  for (const auto& m : models) {
    const auto& r = m.fit.regression;
    s += m.name + ": " + std::to_string(r.samples) + " training samples, rank " + std::to_string(r.rank) +
         ", condition number " + fmt("%.3g", r.conditionNumber) + " (columns scaled)";
    if (m.fit.switchesFitted) {
      const auto& b = m.fit.params.switches;
      s += "\n  switch constants fitted (Ceres, " + std::to_string(m.fit.switchStarts) +
           " starts over the physical ranges): velocity width " + fmt("%.3g", b.velocityWidth) +
           " m/s, position width " + fmt("%.3g", b.positionWidth) + " m, xhy " + fmt("%.3g", b.hyperextensionPosition) +
           " m, latch rate " + fmt("%.3g", b.latchRate) + " /s; training RMSE " + fmt("%.1f", m.fit.trainRmseAtStart) +
           " N at the model file's switches -> " + fmt("%.1f", r.residualRms) + " N";
    }
    s += "\n  phase          f (N)            k (N/m)              c (N s/m)\n";
    for (int i = 0; i < m.fit.params.phases; ++i) {
      const auto& c = m.fit.params.coefficients[static_cast<std::size_t>(i)];
      auto se = [&](int j) { return r.standardErrors[static_cast<std::size_t>(3 * i + j)]; };
      s += "  " + std::to_string(i + 1) + fmt("  %10.2f", c.f) + fmt(" +- %-7.2g", se(0)) + fmt(" %11.1f", c.k) +
           fmt(" +- %-7.2g", se(1)) + fmt(" %10.2f", c.c) + fmt(" +- %-7.2g", se(2)) + "\n";
    }
    std::string flagged;
    for (const auto& k : m.fit.constants) {
      if (k.includesZero) flagged += (flagged.empty() ? "" : ", ") + k.name;
    }
    if (!flagged.empty())
      s += "  95 % confidence interval includes 0 (not distinguishable from no term): " + flagged + "\n";
    for (const auto& c : m.fit.collinear)
      s += "  collinear: " + c.a + " and " + c.b + " (correlation " + fmt("%.3f", c.correlation) +
           "): the data fix a combination of them, not each\n";
    for (const auto& w : m.fit.warnings) s += "  warning: " + w + "\n";
  }
  // Table 2 layout: one row per model, ME / RMSE / R^2 per file.
  if (!models.empty()) {
    s += "\n" + std::string(14, ' ');
    for (const auto& f : models.front().files) {
      char buf[64];
      std::snprintf(buf, sizeof buf, "| %-25s", (f.data->stem + (f.training ? " (train)" : " (validate)")).c_str());
      s += buf;
    }
    s += "\n" + std::string(14, ' ');
    for (std::size_t i = 0; i < models.front().files.size(); ++i) s += "|   ME N  RMSE N  R^2 %   ";
    s += "\n";
    for (const auto& m : models) {
      char buf[32];
      std::snprintf(buf, sizeof buf, "%-14s", m.name.c_str());
      s += buf;
      for (const auto& f : m.files) {
        char cell[64];
        std::snprintf(cell, sizeof cell, "| %6.1f %7.1f %6.1f   ", f.metrics.maxError, f.metrics.rmse,
                      100 * f.metrics.r2);
        s += cell;
      }
      s += "\n";
    }
  }
  return s;
}

std::string formatFitJson(const std::vector<ModelEvaluation>& models) {
  Json list = Json::array();
  for (const auto& m : models) {
    Json coefficients = Json::array();
    for (int i = 0; i < m.fit.params.phases; ++i) {
      const auto& c = m.fit.params.coefficients[static_cast<std::size_t>(i)];
      coefficients.push_back({{"phase", i + 1}, {"f_N", c.f}, {"k_N_per_m", c.k}, {"c_Ns_per_m", c.c}});
    }
    Json metrics = Json::object();
    for (const auto& f : m.files)
      metrics[f.data->stem] = {{"me_N", f.metrics.maxError}, {"rmse_N", f.metrics.rmse}, {"r2", f.metrics.r2}};
    auto bound = [](double v) { return std::abs(v) >= 1e300 ? Json() : Json(v); };  // null: unbounded
    Json constants = Json::array();
    for (const auto& k : m.fit.constants)
      constants.push_back({{"name", k.name},
                           {"value", k.value},
                           {"standard_error", k.standardError},
                           {"lower_bound", bound(k.lower)},
                           {"upper_bound", bound(k.upper)},
                           {"at_bound", k.atBound},
                           {"ci95_includes_zero", k.includesZero}});
    Json collinear = Json::array();
    for (const auto& c : m.fit.collinear) collinear.push_back({{"a", c.a}, {"b", c.b}, {"correlation", c.correlation}});
    const auto& sw = m.fit.params.switches;
    list.push_back({{"model", m.name},
                    {"coefficients", coefficients},
                    {"switches",
                     {{"fitted", m.fit.switchesFitted},
                      {"velocity_width_m_per_s", sw.velocityWidth},
                      {"position_width_m", sw.positionWidth},
                      {"hyperextension_position_m", sw.hyperextensionPosition},
                      {"latch_rate_per_s", sw.latchRate}}},
                    {"constants", constants},
                    {"collinear", collinear},
                    {"warnings", m.fit.warnings},
                    {"metrics", metrics}});
  }
  return formatJson({{"models", list}});
}

namespace {

// Force over time (phases shaded by the dominant gate) above the switch traces.
std::string forcePlot(const ModelEvaluation& m, const FileEvaluation& f, double plotSeconds) {
  const auto& d = *f.data;
  const int phases = m.fit.params.phases;
  std::size_t n = 0;
  while (n < d.time.size() && d.time[n] - d.time.front() <= plotSeconds) ++n;
  auto head = [&](const std::vector<double>& v) {
    return std::vector<double>(v.begin(), v.begin() + static_cast<long>(n));
  };
  const auto t = head(d.time);

  SvgPlot force(800, 380);
  force.setTitle(m.name + " on " + d.stem + (f.training ? " (training)" : " (validation)") + ": RMSE " +
                 fmt("%.1f", f.metrics.rmse) + " N, R^2 " + fmt("%.1f", 100 * f.metrics.r2) + " %");
  force.setXLabel("time (s)");
  force.setYLabel("cylinder force (N)");
  force.setXRange(t.front(), t.back());
  // Shade runs of the dominant phase.
  std::size_t start = 0;
  auto dominant = [&](std::size_t i) {
    const auto& g = f.trace.gates[i];
    int best = 0;
    for (int p = 1; p < phases; ++p)
      if (g[static_cast<std::size_t>(p)] > g[static_cast<std::size_t>(best)]) best = p;
    return best;
  };
  for (std::size_t i = 1; i <= n; ++i) {
    if (i == n || dominant(i) != dominant(start)) {
      const int p = dominant(start);
      force.addBand(t[start], i < n ? t[i] : t[n - 1], "phase " + phaseName(phases, p), phaseColor(p), 0.16);
      start = i;
    }
  }
  force.addLine(t, head(d.force), "measured", "#000000", 1.2);
  force.addLine(t, head(f.trace.force), "predicted", "#E69F00", 1.6);

  SvgPlot sw(800, 250);
  sw.setXLabel("time (s)");
  sw.setYLabel("switch value (-)");
  sw.setXRange(t.front(), t.back());
  sw.setYRange(-0.05, 1.25);
  std::vector<double> s1, s2, s8;
  for (std::size_t i = 0; i < n; ++i) {
    s1.push_back(f.trace.switches[i].s1);
    s2.push_back(f.trace.switches[i].s2);
    s8.push_back(f.trace.switches[i].s8);
  }
  sw.addLine(t, s1, "S1 flexing", "#0072B2", 1.4);
  sw.addLine(t, s2, "S2 latch", "#D55E00", 1.8, true);
  sw.addLine(t, s8, "S8 not hyperextended", "#009E73", 1.4);
  return renderStackedSvg({force, sw});
}

std::string loopPlot(const ModelEvaluation& m, const FileEvaluation& f) {
  const auto& d = *f.data;
  SvgPlot plot(800, 480);
  plot.setTitle(m.name + " on " + d.stem + ": force against piston position (all cycles)");
  plot.setXLabel("piston position x (mm), > 0 = knee flexion");
  plot.setYLabel("cylinder force (N)");
  std::vector<double> xmm;
  for (double x : d.position) xmm.push_back(1e3 * x);
  plot.addLine(xmm, d.force, "measured", "#000000", 1.0);
  plot.addLine(xmm, f.trace.force, "predicted", "#E69F00", 1.4);
  plot.addVLine(1e3 * m.fit.params.switches.hyperextensionPosition, "xhy", "#CC79A7");
  return plot.render();
}

}  // namespace

void writeFitReport(const std::string& outDir, const std::string& studyName, const std::string& command,
                    const std::vector<ModelEvaluation>& models, double plotSeconds) {
  std::string md = "# Cylinder fit: " + studyName + "\n\nCommand: `" + command + "`\n\n";
  md += "Metrics as in Chien 2014 Table 2: ME = maximum absolute force error, RMSE, R^2 (%).\n\n";
  md += "| model | file | role | ME (N) | RMSE (N) | R^2 (%) | time of ME (s) |\n|---|---|---|---|---|---|---|\n";
  std::string csv = "model,phase,f_N,f_se_N,k_N_per_m,k_se_N_per_m,c_Ns_per_m,c_se_Ns_per_m\n";
  for (const auto& m : models) {
    for (const auto& f : m.files) {
      md += "| " + m.name + " | " + f.data->stem + " | " + (f.training ? "train" : "validate") + " | " +
            fmt("%.1f", f.metrics.maxError) + " | " + fmt("%.1f", f.metrics.rmse) + " | " +
            fmt("%.1f", 100 * f.metrics.r2) + " | " + fmt("%.3f", f.data->time[f.metrics.maxErrorIndex]) + " |\n";
    }
    const auto& se = m.fit.regression.standardErrors;
    for (int i = 0; i < m.fit.params.phases; ++i) {
      const auto& c = m.fit.params.coefficients[static_cast<std::size_t>(i)];
      const auto k = static_cast<std::size_t>(3 * i);
      csv += m.name + "," + std::to_string(i + 1) + "," + fmt("%.10g", c.f) + "," + fmt("%.4g", se[k]) + "," +
             fmt("%.10g", c.k) + "," + fmt("%.4g", se[k + 1]) + "," + fmt("%.10g", c.c) + "," + fmt("%.4g", se[k + 2]) +
             "\n";
    }
  }
  md += "\n## Coefficients\n\n```\n" + formatFitTable(models) +
        "```\n\n(coefficients.csv holds them with standard errors)\n";
  for (const auto& m : models) {
    md += "\n## " + m.name + "\n";
    for (const auto& f : m.files) {
      const std::string base = m.name + "-" + f.data->stem;
      writeFileAtomic(outDir + "/" + base + "-force.svg", forcePlot(m, f, plotSeconds));
      writeFileAtomic(outDir + "/" + base + "-loop.svg", loopPlot(m, f));
      md += "\n### " + f.data->stem + (f.training ? " (training)" : " (validation)") + "\n\n![force](" + base +
            "-force.svg)\n\n![loop](" + base + "-loop.svg)\n";
    }
  }
  writeFileAtomic(outDir + "/coefficients.csv", csv);
  writeFileAtomic(outDir + "/report.md", md);
}

}  // namespace swingsim
