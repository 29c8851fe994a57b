#include "swing/sweep.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <map>
#include <thread>

#include "io/input_error.h"
#include "io/participant_loader.h"
#include "io/yaml_reader.h"
#include "swing/burkett_published.h"
#include "swing/knee_setup.h"

namespace swingsim {

namespace {

SweepStudy readSweepStudy(YamlMap& yaml, const std::string& path) {
  SweepStudy s;
  s.path = path;
  yaml.getChoice("kind", {"knee-axis-sweep"}, "");
  s.name = yaml.getString("name");
  yaml.getString("description", "");
  for (const auto& p : yaml.getStringList("participants")) s.participants.push_back(loadParticipant(yaml.resolvePath(p)));
  if (s.participants.empty()) yaml.fail("participants", "expected at least one participant file", "an empty list");
  if (yaml.has("knee_model")) s.kneeModelOverride = yaml.resolvePath(yaml.getString("knee_model"));
  if (yaml.has("com_rule")) {
    // A sensitivity study: the same participants under the other COM reading.
    const bool proportional = yaml.getChoice("com_rule", {"fixed_from_proximal", "proportional"}, "") == "proportional";
    for (auto& p : s.participants) p.comRule = proportional ? ComRule::kProportional : ComRule::kFixedFromProximal;
  }
  if (yaml.has("lowering")) {
    YamlMap m = yaml.getMap("lowering");
    // The grid is rounded to 1 um (sweepLowerings): a smaller step would never advance. With
    // lowerings capped by the shank (calcMaxLowering), this also bounds a sweep to a few
    // thousand swings per participant.
    s.loweringStep = m.getDouble("step_m", s.loweringStep, [](double v) {
      return v >= 1e-4 ? "" : "expected a step of at least 0.0001 m";
    });
    s.loweringMax = m.getDouble("max_m", s.loweringMax, mustBeNonNegative);
    s.includePublishedLowerings = m.getBool("include_published", s.includePublishedLowerings);
    m.finish();
  }
  if (yaml.has("added_mass")) {
    YamlMap m = yaml.getMap("added_mass");
    s.addedMasses = m.getDoubleList("mass_kg");
    s.addedMassDistances = m.getDoubleList("distance_below_knee_m");
    for (double v : s.addedMasses) if (v < 0) m.fail("mass_kg", "masses must not be negative", formatNumber(v));
    for (double v : s.addedMassDistances) if (v < 0) m.fail("distance_below_knee_m", "distances must not be negative", formatNumber(v));
    if (s.addedMassDistances.empty()) m.fail("distance_below_knee_m", "expected at least one distance", "an empty list");
    m.finish();
  }
  if (yaml.has("integrator")) {
    YamlMap m = yaml.getMap("integrator");
    const std::vector<std::string>& keys = integratorKeys();
    const std::string method = m.getChoice("method", keys, keys[static_cast<int>(s.swing.integrator)]);
    s.swing.integrator = *findIntegrator(method);  // getChoice allowed only known keys
    s.swing.accuracy = m.getDouble("accuracy", s.swing.accuracy, [](double v) { return checkAccuracy(v); });
    s.swing.sampleInterval = m.getDouble("sample_interval_s", s.swing.sampleInterval, [](double v) {
      return v >= 1e-5 && v <= 0.1 ? "" : "expected a sample interval from 0.00001 to 0.1 s";
    });
    m.finish();
  }
  s.outputDir = yaml.getString("output_dir", "");
  yaml.finish();
  return s;
}

}  // namespace

SweepStudy loadSweepStudy(const std::string& path) {
  YamlMap yaml = YamlMap::loadFile(path);
  return readSweepStudy(yaml, path);
}

SweepStudy parseSweepStudy(const std::string& text, const std::string& path) {
  YamlMap yaml = YamlMap::loadString(text, path);
  return readSweepStudy(yaml, path);
}

std::vector<double> sweepLowerings(const SweepStudy& study, const Participant& p) {
  const double cap = std::min(study.loweringMax, calcMaxLowering(p));
  std::vector<double> out;
  // Integer steps, so 0.1 is exactly 10 steps of 0.01 and results do not drift.
  for (int i = 0;; ++i) {
    const double d = std::round(i * study.loweringStep * 1e6) / 1e6;
    if (d > cap + 1e-9) break;
    out.push_back(d);
  }
  if (study.includePublishedLowerings) {
    if (const PublishedParticipant* pub = findPublished(p.name)) {
      for (const auto& row : pub->table4) {
        bool onGrid = false;
        for (double d : out) onGrid = onGrid || std::fabs(d - row.lowering) < 1e-9;
        if (!onGrid && row.lowering <= calcMaxLowering(p) + 1e-9) out.push_back(row.lowering);
      }
      std::sort(out.begin(), out.end());
    }
  }
  return out;
}

namespace {

struct Job {
  std::size_t participant;
  bool withMass;
  std::size_t index;  // into points or massPoints
};

}  // namespace

SweepResults runSweep(const SweepStudy& study, int jobs, const std::function<void(int, int)>& progress,
                      const volatile bool* stopFlag) {
  SweepResults results;
  results.study = study.name;
  std::vector<KneeLawSum> knees;
  std::vector<Job> work;
  std::map<std::string, KneeModel> models;
  for (std::size_t i = 0; i < study.participants.size(); ++i) {
    const Participant& p = study.participants[i];
    const std::string modelPath = study.kneeModelOverride.empty() ? p.kneeModelPath : study.kneeModelOverride;
    if (!models.count(modelPath)) models.emplace(modelPath, loadKneeModel(modelPath));
    knees.push_back(makeKneeLaw(p, models.at(modelPath)));

    ParticipantSweep ps;
    ps.name = p.name;
    const auto lowerings = sweepLowerings(study, p);
    ps.loweringCap = std::min(study.loweringMax, calcMaxLowering(p));
    if (study.loweringMax > calcMaxLowering(p) + 1e-9) {
      ps.capNote = "lowering capped at " + formatNumber(ps.loweringCap) + " m (study asks " +
                   formatNumber(study.loweringMax) + " m): below that the shank COM would leave the shank or less than " +
                   formatNumber(p.minShankLength) + " m of shank would remain";
    }
    for (double d : lowerings) {
      SweepPoint pt;
      pt.lowering = d;
      pt.onGrid = d <= study.loweringMax + 1e-9 &&
                  std::fabs(d / study.loweringStep - std::round(d / study.loweringStep)) < 1e-6;
      ps.points.push_back(pt);
      work.push_back({i, false, ps.points.size() - 1});
      for (double m : study.addedMasses) {
        if (m <= 0) continue;
        for (double at : study.addedMassDistances) {
          if (at > p.shank.length - d) continue;  // the mass must sit on the shortened shank
          SweepPoint mp;
          mp.lowering = d;
          mp.onGrid = pt.onGrid;
          mp.added = {m, at};
          ps.massPoints.push_back(mp);
          work.push_back({i, true, ps.massPoints.size() - 1});
        }
      }
    }
    results.participants.push_back(std::move(ps));
  }

  const int total = static_cast<int>(work.size());
  std::atomic<int> next{0}, done{0};
  auto runOne = [&](const Job& job) {
    const Participant& p = study.participants[job.participant];
    ParticipantSweep& ps = results.participants[job.participant];
    SweepPoint& pt = job.withMass ? ps.massPoints[job.index] : ps.points[job.index];
    SwingSetup setup;
    setup.participant = p;
    setup.knee = &knees[job.participant];
    setup.lowering = pt.lowering;
    setup.added = pt.added;
    SwingOptions options = study.swing;
    options.recordTrajectory = !job.withMass;
    try {
      pt.result = simulateSwing(setup, options);
      pt.ok = true;
    } catch (const RunError& e) {
      pt.failure = e.what();
    }
    pt.ran = true;
  };
  auto worker = [&] {
    for (;;) {
      if (stopFlag && *stopFlag) return;
      const int k = next.fetch_add(1);
      if (k >= total) return;
      runOne(work[static_cast<std::size_t>(k)]);
      done.fetch_add(1);
    }
  };
  int threads = jobs > 0 ? jobs : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  threads = std::min(threads, std::max(1, total));
  // Workers pull jobs by index; the calling thread only reports progress.
  std::vector<std::thread> pool;
  for (int t = 0; t < threads; ++t) pool.emplace_back(worker);
  while (progress && done.load() < total && !(stopFlag && *stopFlag)) {
    progress(done.load(), total);
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    if (done.load() >= total) break;
  }
  for (auto& t : pool) t.join();
  if (progress) progress(done.load(), total);

  for (auto& ps : results.participants) {
    auto pickBest = [](std::vector<SweepPoint>& pts) {
      int best = -1;
      for (std::size_t k = 0; k < pts.size(); ++k) {
        if (!pts[k].ran) pts[k].failure = "not run (interrupted)";
        if (pts[k].ok && pts[k].onGrid && (best < 0 || pts[k].result.swingTime < pts[static_cast<std::size_t>(best)].result.swingTime - 1e-12))
          best = static_cast<int>(k);
      }
      return best;
    };
    ps.best = pickBest(ps.points);
    ps.bestWithMass = pickBest(ps.massPoints);
  }
  return results;
}

}  // namespace swingsim
