#include "identify/cylinder_diagnosis.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/input_error.h"

namespace swingsim {

namespace {

// chi^2(1) 95 % quantile, for the profile-likelihood interval of a grid parameter.
constexpr double kChi2One95 = 3.841458820694124;
// Latch rate of Chien 2014 (k = 1e4 /s): the no-delay reference for switch_delay.
constexpr double kPublishedLatchRate = 1e4;

std::string fmt(double v, const char* f = "%.3g") {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

}  // namespace

const std::vector<CylinderEffectInfo>& cylinderEffectLibrary() {
  static const std::vector<CylinderEffectInfo> lib = {
      {"coulomb_friction",
       "a seal friction force of constant size that always opposes the piston's motion",
       "Chien 2014 tried a Coulomb term opposing motion (it made their fit worse)",
       "records at several speeds (its size does not grow with speed)"},
      {"orifice_quadratic",
       "extra resistance growing with the square of piston speed: turbulent flow through the orifices",
       "Chien 2014: slow gait fits worst, likely non-linear flow through cylinder, orifices and valve",
       "records at clearly different speeds (slow and fast walking)"},
      {"inertia",
       "a force proportional to piston acceleration: the moving mass of piston, rod and oil",
       "Chien 2014 tried an acceleration term (it did not help on their data)",
       "records with different frequency content (another cadence or a sine sweep)"},
      {"position_dependent_damping",
       "damping that changes along the stroke (metering grooves, valve opening with position)",
       "Chien 2014's phases have constant damping; the valve geometry varies along the stroke",
       "records with different knee-angle amplitudes"},
      {"hyperextension_phase",
       "a separate force law while the piston is hyperextended (Chien's 4th phase)",
       "Chien 2014 Eq. 11: the 4-phase model adds hyperextension to the 2-phase model",
       "records with longer or deeper hyperextension"},
      {"switch_delay",
       "the valve latch (balance wheel) needs time to turn: swing flexion starts partly with stance resistance",
       "Chien 2014 discussion: the balance-wheel release timing (about 0.1 s) is not reproduced by fast switches",
       "records with longer hyperextension holds (a slow latch completes given time)"},
  };
  return lib;
}

const CylinderEffectInfo& findCylinderEffect(const std::string& name) {
  for (const auto& e : cylinderEffectLibrary())
    if (e.name == name) return e;
  throw std::invalid_argument("unknown cylinder effect '" + name + "'");
}

const std::vector<double>& coulombWidthGrid() {
  static const std::vector<double> g = {0.002, 0.005, 0.01, 0.02, 0.05};
  return g;
}

const std::vector<double>& latchTimeConstantGrid() {
  static const std::vector<double> g = {0.001, 0.002, 0.005, 0.01, 0.02, 0.05, 0.1};
  return g;
}

std::string checkCylinderEffectApplicable(const MauchCylinderParams& p, const std::string& effect) {
  const auto& e = p.effects;
  if (effect == "coulomb_friction" && e.coulombFriction) return "already in the model";
  if (effect == "orifice_quadratic" && e.orificeQuadratic) return "already in the model";
  if (effect == "inertia" && e.inertia) return "already in the model";
  if (effect == "position_dependent_damping" && e.positionDependentDamping) return "already in the model";
  if (effect == "hyperextension_phase") {
    if (p.phases != 2) return "the 4-phase model already has a hyperextension phase";
    if (e.hyperextensionPhase) return "already in the model";
  }
  if (effect == "switch_delay" && 1.0 / p.switches.latchRate >= latchTimeConstantGrid().front())
    return "the model's latch is already slow (k = " + formatNumber(p.switches.latchRate) + " /s)";
  return "";
}

MauchCylinderParams addCylinderEffect(const MauchCylinderParams& params, const std::string& effect, double nonlinear) {
  MauchCylinderParams p = params;
  auto& e = p.effects;
  if (effect == "coulomb_friction") {
    e.coulombFriction = true;
    e.coulombForce = 0;
    e.coulombWidth = nonlinear;
  } else if (effect == "orifice_quadratic") {
    e.orificeQuadratic = true;
    e.orificeCoefficient = 0;
  } else if (effect == "inertia") {
    e.inertia = true;
    e.pistonMass = 0;
  } else if (effect == "position_dependent_damping") {
    e.positionDependentDamping = true;
    e.positionDamping = 0;
  } else if (effect == "hyperextension_phase") {
    e.hyperextensionPhase = true;
    e.hyperextension = {};
  } else if (effect == "switch_delay") {
    p.switches.latchRate = 1.0 / nonlinear;
  } else {
    throw std::invalid_argument("unknown cylinder effect '" + effect + "'");
  }
  return p;
}

namespace {

// The non-linear grid of an effect (one value, unused, for linear effects).
std::vector<double> gridOf(const std::string& effect) {
  if (effect == "coulomb_friction") return coulombWidthGrid();
  if (effect == "switch_delay") return latchTimeConstantGrid();
  return {0.0};
}

// Regression columns of the added effects, in MauchCylinder::calcRegressorRow's order.
std::vector<int> effectColumns(const MauchCylinderParams& p, const std::string& effect) {
  int col = 3 * p.phases;
  const auto& e = p.effects;
  std::vector<int> cols;
  auto take = [&](bool on, int count, const char* name) {
    if (!on) return;
    if (effect == name)
      for (int i = 0; i < count; ++i) cols.push_back(col + i);
    col += count;
  };
  take(e.hyperextensionPhase, 3, "hyperextension_phase");
  take(e.coulombFriction, 1, "coulomb_friction");
  take(e.orificeQuadratic, 1, "orifice_quadratic");
  take(e.inertia, 1, "inertia");
  take(e.positionDependentDamping, 1, "position_dependent_damping");
  return cols;
}

// A model fitted to the training files and run along all files.
struct Scored {
  MauchCylinderParams params;
  LinearFit regression;
  ResidualSegments trainResidual;
  double trainRss = 0;
  std::size_t trainSamples = 0;
  std::vector<double> validationRmse;
  std::vector<std::vector<int>> trainPhase;  // dominant gate per training sample
};

std::vector<double> residualOf(const MauchCylinder& cyl, const BenchData& d, std::vector<int>* phase = nullptr) {
  const CylinderTrace tr = calcCylinderTrace(cyl, d.time, d.position, d.velocity, 0.0);
  std::vector<double> r(d.force.size());
  for (std::size_t i = 0; i < r.size(); ++i) r[i] = d.force[i] - tr.force[i];
  if (phase) {
    phase->resize(r.size());
    for (std::size_t i = 0; i < r.size(); ++i)
      (*phase)[i] = static_cast<int>(std::max_element(tr.gates[i].begin(), tr.gates[i].end()) - tr.gates[i].begin());
  }
  return r;
}

double rmsOf(const std::vector<double>& r) {
  double s = 0;
  for (double v : r) s += v * v;
  return r.empty() ? 0.0 : std::sqrt(s / static_cast<double>(r.size()));
}

Scored fitAndScore(const MauchCylinderParams& params, const std::vector<BenchData>& train,
                   const std::vector<BenchData>& validate, bool withPhases = false) {
  Scored s;
  const CylinderFit fit = fitCylinder(params, train);
  s.params = fit.params;
  s.regression = fit.regression;
  const MauchCylinder cyl(s.params);
  for (const auto& d : train) {
    std::vector<int> phase;
    s.trainResidual.push_back(residualOf(cyl, d, withPhases ? &phase : nullptr));
    if (withPhases) s.trainPhase.push_back(phase);
    for (double r : s.trainResidual.back()) s.trainRss += r * r;
    s.trainSamples += d.force.size();
  }
  for (const auto& d : validate) s.validationRmse.push_back(rmsOf(residualOf(cyl, d)));
  return s;
}

// Likelihood-ratio statistics of `bigger` against `smaller` (nested, `dof` more parameters).
LrTest calcLrTest(const Scored& smaller, const Scored& bigger, int dof) {
  return swingsim::calcLrTest(smaller.trainRss, bigger.trainRss, bigger.trainResidual, dof);
}

std::string physicalCheck(const MauchCylinderParams& p, const std::string& effect, const std::vector<BenchData>& train,
                          bool& ok) {
  const auto& e = p.effects;
  if (effect == "coulomb_friction") {
    ok = e.coulombForce > 0;
    return "friction force must oppose motion (force_N > 0): " + fmt(e.coulombForce) + " N";
  }
  if (effect == "orifice_quadratic") {
    ok = e.orificeCoefficient > 0;
    return "orifice flow must resist motion (coefficient > 0): " + fmt(e.orificeCoefficient) + " N s^2/m^2";
  }
  if (effect == "inertia") {
    ok = e.pistonMass > 0;
    return "moving mass must be positive: " + fmt(e.pistonMass) + " kg";
  }
  if (effect == "hyperextension_phase") {
    ok = e.hyperextension.k > 0;
    return "hyperextension stiffness must push the piston out of hyperextension (k > 0): " + fmt(e.hyperextension.k) +
           " N/m";
  }
  if (effect == "switch_delay") {
    ok = true;
    return "latch time constant 1/k > 0: " + fmt(1.0 / p.switches.latchRate) + " s";
  }
  // position_dependent_damping: every flexion/extension phase keeps non-negative damping
  // c + cx x over the recorded stroke (a negative damper would feed energy in).
  double xMin = 1e300, xMax = -1e300;
  for (const auto& d : train)
    for (double x : d.position) {
      xMin = std::max(0.0, std::min(xMin, x));
      xMax = std::max(xMax, x);
    }
  double worst = 1e300;
  const int flexExtPhases = p.phases == 4 ? 3 : 2;
  for (int ph = 0; ph < flexExtPhases; ++ph) {
    const double c = p.coefficients[static_cast<std::size_t>(ph)].c;
    worst = std::min({worst, c + e.positionDamping * xMin, c + e.positionDamping * xMax});
  }
  ok = worst >= 0;
  return "damping c + cx x must stay >= 0 over the stroke: lowest " + fmt(worst) + " N s/m";
}

}  // namespace

std::vector<EffectParameter> getCylinderEffectParameters(const MauchCylinderParams& p, const std::string& effect) {
  const auto& e = p.effects;
  if (effect == "coulomb_friction" && e.coulombFriction)
    return {{"force_N", e.coulombForce, e.coulombForce, e.coulombForce},
            {"width_m_per_s", e.coulombWidth, e.coulombWidth, e.coulombWidth}};
  if (effect == "orifice_quadratic" && e.orificeQuadratic)
    return {{"coefficient_Ns2_per_m2", e.orificeCoefficient, e.orificeCoefficient, e.orificeCoefficient}};
  if (effect == "inertia" && e.inertia) return {{"mass_kg", e.pistonMass, e.pistonMass, e.pistonMass}};
  if (effect == "position_dependent_damping" && e.positionDependentDamping)
    return {{"coefficient_Ns_per_m2", e.positionDamping, e.positionDamping, e.positionDamping}};
  if (effect == "hyperextension_phase" && e.hyperextensionPhase)
    return {{"f_N", e.hyperextension.f, e.hyperextension.f, e.hyperextension.f},
            {"k_N_per_m", e.hyperextension.k, e.hyperextension.k, e.hyperextension.k},
            {"c_Ns_per_m", e.hyperextension.c, e.hyperextension.c, e.hyperextension.c}};
  if (effect == "switch_delay") {
    const double tau = 1.0 / p.switches.latchRate;
    return {{"time_constant_s", tau, tau, tau}};
  }
  return {};
}

std::vector<std::string> cylinderPhaseNames(const MauchCylinderParams& p) {
  std::vector<std::string> names = p.phases == 4
                                       ? std::vector<std::string>{"stance flexion", "swing flexion", "extension",
                                                                  "hyperextension"}
                                       : std::vector<std::string>{"stance flexion (high force)", "low force"};
  if (p.effects.hyperextensionPhase) names.push_back("hyperextension");
  return names;
}

CylinderComparison compareCylinder(const MauchCylinderParams& model, const std::vector<BenchData>& train,
                                   const std::vector<BenchData>& validate) {
  CylinderComparison out;
  out.phaseNames = cylinderPhaseNames(model);
  const MauchCylinder cyl(model);
  const std::size_t phases = out.phaseNames.size();
  auto run = [&](const BenchData& d, bool training) {
    RecordComparison rc;
    rc.data = &d;
    rc.training = training;
    const CylinderTrace tr = calcCylinderTrace(cyl, d.time, d.position, d.velocity, 0.0);
    rc.predicted = tr.force;
    rc.acceleration = estimatePistonVelocity(d.time, d.velocity);
    rc.residual.resize(d.force.size());
    rc.phase.resize(d.force.size());
    for (std::size_t i = 0; i < d.force.size(); ++i) {
      rc.residual[i] = d.force[i] - tr.force[i];
      rc.phase[i] = static_cast<int>(std::max_element(tr.gates[i].begin(), tr.gates[i].end()) - tr.gates[i].begin());
    }
    rc.overall = calcErrorMetrics(d.force, rc.predicted);
    double total = 0;
    for (double r : rc.residual) total += r * r;
    for (std::size_t ph = 0; ph < phases; ++ph) {
      std::vector<bool> mask(d.force.size());
      double sq = 0;
      std::size_t count = 0;
      for (std::size_t i = 0; i < mask.size(); ++i) {
        mask[i] = rc.phase[i] == static_cast<int>(ph);
        if (mask[i]) {
          sq += rc.residual[i] * rc.residual[i];
          ++count;
        }
      }
      rc.perPhase.push_back(calcErrorMetrics(d.force, rc.predicted, mask));
      rc.phaseShare.push_back(total > 0 ? sq / total : 0.0);
      rc.sampleShare.push_back(static_cast<double>(count) / static_cast<double>(mask.size()));
    }
    out.records.push_back(std::move(rc));
  };
  for (const auto& d : train) run(d, true);
  for (const auto& d : validate) run(d, false);
  return out;
}

double calcCylinderEffectRms(const MauchCylinderParams& truth, const std::string& effect, const BenchData& record) {
  MauchCylinderParams without = truth;
  auto& e = without.effects;
  if (effect == "coulomb_friction") e.coulombFriction = false;
  else if (effect == "orifice_quadratic") e.orificeQuadratic = false;
  else if (effect == "inertia") e.inertia = false;
  else if (effect == "position_dependent_damping") e.positionDependentDamping = false;
  else if (effect == "hyperextension_phase") {
    e.hyperextensionPhase = false;
  } else if (effect == "switch_delay") {
    without.switches.latchRate = kPublishedLatchRate;
  } else {
    throw std::invalid_argument("unknown cylinder effect '" + effect + "'");
  }
  const auto a = calcCylinderTrace(MauchCylinder(truth), record.time, record.position, record.velocity, 0.0).force;
  const auto b = calcCylinderTrace(MauchCylinder(without), record.time, record.position, record.velocity, 0.0).force;
  double s = 0;
  for (std::size_t i = 0; i < a.size(); ++i) s += (a[i] - b[i]) * (a[i] - b[i]);
  return a.empty() ? 0.0 : std::sqrt(s / static_cast<double>(a.size()));
}

namespace {

// Scores one candidate on top of `current`: every existing coefficient refitted with it, its
// non-linear parameter profiled on the fixed grid (best training RSS).
CandidateScore scoreCandidate(const Scored& current, const std::string& effect, const std::vector<BenchData>& train,
                              const std::vector<BenchData>& validate, const CylinderDiagnosisSettings& settings,
                              Scored* bestOut) {
  CandidateScore c;
  c.effect = effect;
  c.notApplicable = checkCylinderEffectApplicable(current.params, effect);
  if (!c.notApplicable.empty()) return c;
  const auto grid = gridOf(effect);
  std::vector<Scored> fits;
  std::size_t best = 0;
  for (double g : grid) {
    try {
      fits.push_back(fitAndScore(addCylinderEffect(current.params, effect, g), train, validate));
    } catch (const RunError& e) {
      c.notApplicable = e.what();
      return c;
    }
    if (fits.back().trainRss < fits[best].trainRss) best = fits.size() - 1;
  }
  const Scored& s = fits[best];
  const int linear = static_cast<int>(effectColumns(s.params, effect).size());
  const int dof = linear + (grid.size() > 1 ? 1 : 0);
  const LrTest t = calcLrTest(current, s, dof);
  c.params = s.params;
  c.trainRmse = std::sqrt(s.trainRss / static_cast<double>(s.trainSamples));
  c.validationRmse = s.validationRmse;
  applyTestAndValidation(c, t, dof, current.validationRmse, settings);
  // Parameters with 95 % intervals: regression standard errors inflated by sqrt(n / n_eff)
  // for autocorrelated residuals; a grid parameter by its profile likelihood over the grid.
  c.parameters = getCylinderEffectParameters(s.params, effect);
  const auto cols = effectColumns(s.params, effect);
  const double inflate = calcStandardErrorInflation(static_cast<double>(s.trainSamples), t.nEff);
  for (std::size_t k = 0; k < cols.size() && k < c.parameters.size(); ++k)
    setNormalInterval(c.parameters[k], s.regression.standardErrors[static_cast<std::size_t>(cols[k])] * inflate);
  if (grid.size() > 1) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (std::size_t g = 0; g < grid.size(); ++g) {
      if (t.nEff * std::log(fits[g].trainRss / s.trainRss) <= kChi2One95) {
        lo = std::min(lo, grid[g]);
        hi = std::max(hi, grid[g]);
      }
    }
    auto& gp = c.parameters.back();  // width or time constant: the last named parameter
    gp.lower = lo;
    gp.upper = hi;
  }
  c.physicalNote = physicalCheck(s.params, effect, train, c.physical);
  c.physicalNote += c.physical ? " (ok)" : " (wrong sign)";
  // Where the squared error fell most, by the current model's phases.
  const auto names = cylinderPhaseNames(current.params);
  std::vector<double> fall(names.size(), 0.0);
  double totalFall = 0;
  for (std::size_t f = 0; f < train.size(); ++f)
    for (std::size_t i = 0; i < current.trainResidual[f].size(); ++i) {
      const double d = current.trainResidual[f][i] * current.trainResidual[f][i] - s.trainResidual[f][i] * s.trainResidual[f][i];
      fall[static_cast<std::size_t>(current.trainPhase[f][i])] += d;
      totalFall += d;
    }
  const std::size_t where = static_cast<std::size_t>(std::max_element(fall.begin(), fall.end()) - fall.begin());
  c.where = names[where] + (totalFall > 0 ? " (" + fmt(100.0 * fall[where] / totalFall, "%.0f") + " % of the error fall)" : "");
  for (const auto& r : s.trainResidual) c.trainResidual.insert(c.trainResidual.end(), r.begin(), r.end());
  if (bestOut) *bestOut = s;
  return c;
}

// Both effects of two fitted candidates in one model (grid values kept).
MauchCylinderParams combine(const MauchCylinderParams& a, const MauchCylinderParams& b) {
  MauchCylinderParams p = a;
  const auto& e = b.effects;
  if (e.coulombFriction) {
    p.effects.coulombFriction = true;
    p.effects.coulombWidth = e.coulombWidth;
  }
  p.effects.orificeQuadratic |= e.orificeQuadratic;
  p.effects.inertia |= e.inertia;
  p.effects.positionDependentDamping |= e.positionDependentDamping;
  p.effects.hyperextensionPhase |= e.hyperextensionPhase;
  p.switches.latchRate = std::min(a.switches.latchRate, b.switches.latchRate);
  return p;
}

std::string describeStructure(const MauchCylinderParams& model, const std::vector<BenchData>& train) {
  const CylinderComparison cmp = compareCylinder(model, train, {});
  // The phase with the largest excess of squared error over its share of samples.
  std::string out;
  double bestExcess = -1;
  const auto& rc = cmp.records.front();
  for (std::size_t ph = 0; ph < cmp.phaseNames.size(); ++ph) {
    const double excess = rc.phaseShare[ph] - rc.sampleShare[ph];
    if (excess > bestExcess) {
      bestExcess = excess;
      out = "the largest share of squared error is in " + cmp.phaseNames[ph] + " (" + fmt(100 * rc.phaseShare[ph], "%.0f") +
            " % of the error in " + fmt(100 * rc.sampleShare[ph], "%.0f") + " % of the samples)";
    }
  }
  ResidualSegments seg;
  std::vector<double> x, v, a, r;
  for (const auto& c : cmp.records) {
    seg.push_back(c.residual);
    x.insert(x.end(), c.data->position.begin(), c.data->position.end());
    v.insert(v.end(), c.data->velocity.begin(), c.data->velocity.end());
    a.insert(a.end(), c.acceleration.begin(), c.acceleration.end());
    r.insert(r.end(), c.residual.begin(), c.residual.end());
  }
  const double ratio = calcEffectiveSampleSize(seg) / static_cast<double>(r.size());
  struct Var {
    const char* name;
    const std::vector<double>* values;
    double scale;
    const char* unit;
  };
  const Var vars[] = {{"position", &x, 1e3, "mm"}, {"velocity", &v, 1e3, "mm/s"}, {"acceleration", &a, 1.0, "m/s^2"}};
  double best = 0;
  std::string binNote;
  for (const auto& var : vars) {
    const BinnedResidual b = calcBinnedResidual(*var.values, r, 12, ratio);
    if (b.maxSignificance > best && !b.center.empty()) {
      best = b.maxSignificance;
      binNote = "; the binned mean residual departs most from zero at " + std::string(var.name) + " " +
                fmt(b.center[b.maxBin] * var.scale) + " " + var.unit + " (mean " + fmt(b.mean[b.maxBin]) + " N, " +
                fmt(b.maxSignificance, "%.1f") + " x its 99 % half-width)";
    }
  }
  return out + binNote;
}

}  // namespace

CylinderDiagnosis diagnoseCylinder(const MauchCylinderParams& base, const std::vector<BenchData>& train,
                                   const std::vector<BenchData>& validate, const CylinderDiagnosisSettings& settings) {
  if (validate.empty())
    throw InputError("diagnose: the acceptance rule needs at least one validation file (validate:)");
  std::vector<std::string> library;
  for (const auto& e : cylinderEffectLibrary()) library.push_back(e.name);
  const std::vector<std::string> names = resolveCandidates(settings.candidates, library);
  CylinderDiagnosis out;
  MauchCylinderParams start = base;
  if (settings.fitSwitches) {
    CylinderFitOptions o;
    o.fitSwitches = true;
    const CylinderFit f = fitCylinder(base, train, o);
    start = f.params;
    out.warnings = f.warnings;
  }
  Scored current = fitAndScore(start, train, validate, true);
  out.baseline = current.params;
  out.baselineWhiteness = calcWhitenessTest(current.trainResidual, settings.whitenessLags);

  for (int stepNo = 0; stepNo < settings.maxEffects; ++stepNo) {
    DiagnosisStep step;
    step.currentTrainRmse = std::sqrt(current.trainRss / static_cast<double>(current.trainSamples));
    step.currentValidationRmse = current.validationRmse;
    std::vector<Scored> best(names.size());
    int applicable = 0;
    for (std::size_t i = 0; i < names.size(); ++i) {
      step.candidates.push_back(scoreCandidate(current, names[i], train, validate, settings, &best[i]));
      if (step.candidates.back().notApplicable.empty()) ++applicable;
    }
    if (applicable == 0) {
      out.steps.push_back(step);
      break;
    }
    std::vector<EffectScore*> scores;
    for (auto& c : step.candidates) scores.push_back(&c);
    step.chosen = applyAcceptanceRule(scores, settings.alpha);
    if (step.chosen < 0) {
      out.steps.push_back(step);
      break;
    }
    const auto chosen = static_cast<std::size_t>(step.chosen);
    step.group = findAmbiguityGroup(scores, names, chosen, settings.alpha, [&](std::size_t j) -> std::optional<double> {
      Scored joint;
      try {
        joint = fitAndScore(combine(best[j].params, best[chosen].params), train, validate);
      } catch (const RunError&) {
        return std::nullopt;
      }
      const int dofChosen = static_cast<int>(effectColumns(joint.params, names[chosen]).size()) +
                            (gridOf(names[chosen]).size() > 1 ? 1 : 0);
      return calcLrTest(best[j], joint, std::max(1, dofChosen)).p;
    });
    current = best[chosen];
    {
      // Phases of the new model for the next step's "where".
      Scored withPhases = fitAndScore(current.params, train, validate, true);
      current = withPhases;
    }
    out.accepted.push_back(names[chosen]);
    out.acceptedScores.push_back(step.candidates[chosen]);
    recordAmbiguity(step.group, [](const std::string& e) { return findCylinderEffect(e).separatedBy; }, out.ambiguous,
                    out.ambiguityAdvice);
    out.steps.push_back(step);
  }
  out.final = current.params;
  out.finalWhiteness = calcWhitenessTest(current.trainResidual, settings.whitenessLags);
  out.finalResidualWhite = out.finalWhiteness.pValue >= settings.alpha;
  if (!out.finalResidualWhite) out.structureNote = describeStructure(out.final, train);
  return out;
}

}  // namespace swingsim
