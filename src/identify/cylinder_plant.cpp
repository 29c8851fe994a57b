#include "identify/cylinder_plant.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <stdexcept>

#include "core/input_error.h"
#include "identify/cylinder_effects.h"
#include "identify/cylinder_regression.h"
#include "identify/missing_force.h"
#include "identify/user_cylinder_effect.h"

namespace swingsim {

namespace {

// Force and dominant gate of a model along one record (S2 = 0 at heel strike).
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

// Polishes after a joint refit's multi-start fit, while the training RMSE falls by more than
// this fraction (1e-5: far below what the likelihood ratio of one added constant can see).
constexpr int kRefitPolishes = 4;
constexpr double kRefitPolishFall = 1e-5;

// The switch constants a fit freed (fitCylinder's constants after the coefficients) as the
// engine's base parameters: value, standard error from the joint covariance, physical range.
std::vector<PlantFit::FreeParameter> freedSwitchConstants(const CylinderFit& fitted) {
  std::vector<PlantFit::FreeParameter> out;
  for (std::size_t j = fitted.regression.coefficients.size(); j < fitted.constants.size(); ++j) {
    const FittedConstant& c = fitted.constants[j];
    out.push_back({c.name, c.value, c.standardError, c.lower, c.upper});
  }
  return out;
}

// Whether the 4-phase split of a 2-phase model with a hyperextension phase is supported:
// the acceptance rule's test on its 3 more coefficients (default alpha and BIC) and every
// held-out RMSE lower by the rule's margin.
bool supportsSplit(const PlantFit& merged, const PlantFit& split) {
  const EffectSelectionSettings rule;
  constexpr int kSplitCoefficients = 3;
  const LrTest t = calcLrTest(merged.rss, split.rss, split.likelihoodResidual, kSplitCoefficients);
  EffectScore score;
  score.validationRmse = split.validationRmse;
  applyTestAndValidation(score, t, kSplitCoefficients, merged.validationRmse, rule);
  return t.p < rule.alpha && score.bicImproves && score.validationImproves;
}

}  // namespace

const MauchCylinderParams& cylinderParams(const PlantModel& model) {
  return dynamic_cast<const CylinderModel&>(model).params;
}

std::string checkCylinderEffectApplicable(const MauchCylinderParams& p, EffectId effect) {
  const CylinderEffectRecord& r = findCylinderEffectRecord(effect);
  if (r.notApplicable) {
    std::string why = r.notApplicable(p);
    if (!why.empty()) return why;
  }
  return r.has(p) ? "already in the model" : "";
}

MauchCylinderParams addCylinderEffect(const MauchCylinderParams& params, EffectId effect, double gridValue) {
  MauchCylinderParams p = params;
  findCylinderEffectRecord(effect).add(p, gridValue);
  return p;
}

std::vector<std::string> cylinderPhaseNames(const MauchCylinderParams& p) {
  std::vector<std::string> names =
      p.phases == 4 ? std::vector<std::string>{"stance flexion", "swing flexion", "extension", "hyperextension"}
                    : std::vector<std::string>{"stance flexion (high force)", "low force"};
  if (p.effects.hyperextensionPhase) names.push_back("hyperextension");
  return names;
}

double calcCylinderEffectRms(const MauchCylinderParams& truth, EffectId effect, const BenchData& record) {
  MauchCylinderParams without = truth;
  findCylinderEffectRecord(effect).remove(without);
  const auto a = calcCylinderTrace(MauchCylinder(truth), record.time, record.position, record.velocity, 0.0).force;
  const auto b = calcCylinderTrace(MauchCylinder(without), record.time, record.position, record.velocity, 0.0).force;
  double s = 0;
  for (std::size_t i = 0; i < a.size(); ++i) s += (a[i] - b[i]) * (a[i] - b[i]);
  return a.empty() ? 0.0 : std::sqrt(s / static_cast<double>(a.size()));
}

CylinderPlant::CylinderPlant(const MauchCylinderParams& base, std::vector<BenchData> train,
                             std::vector<BenchData> validate, bool fitSwitches, double plotSeconds)
    : start_(base),
      train_(std::move(train)),
      validate_(std::move(validate)),
      plotSeconds_(plotSeconds),
      fitSwitches_(fitSwitches) {
  if (fitSwitches) {
    CylinderFitOptions o;
    o.fitSwitches = true;
    // The latch rate stays the switch_delay candidate's: a normal-speed record alone rarely
    // determines it (its hyperextension hold suits a slow and a fast latch alike), and the
    // candidate is judged on held-out records, which do.
    o.fitLatchRate = false;
    const CylinderFit f = fitCylinder(base, train_, o);
    start_ = f.params;
    warnings_ = f.warnings;
  }
}

PlantModelPtr CylinderPlant::baseModel() const { return std::make_shared<CylinderModel>(start_); }

namespace {
const CylinderModel& asCylinderModel(const PlantModel& model) { return dynamic_cast<const CylinderModel&>(model); }
}  // namespace

namespace {

// One parameter of a user's expression in a model, as a free parameter of the fit.
struct ExpressionSlot {
  EffectId effect;
  std::size_t expression, parameter;
  BoundedParameter bounds;
};

// The parameters of the model's registered users' expressions (an expression of the base
// model's file that no study states stays as it is), each starting from its present value.
std::vector<ExpressionSlot> findExpressionSlots(const MauchCylinderParams& p) {
  std::vector<ExpressionSlot> out;
  for (std::size_t i = 0; i < p.effects.expressions.size(); ++i) {
    const KneeExpressionParams& x = p.effects.expressions[i];
    const EffectDescriptor* d = findEffect(PlantKind::kCylinder, x.name);
    const CylinderEffectRecord* r = d ? findUserCylinderEffectRecord(d->id) : nullptr;
    if (!r || r->expressionBounds.size() != x.parameters.size()) continue;
    for (std::size_t j = 0; j < x.parameters.size(); ++j) {
      BoundedParameter b = r->expressionBounds[j];
      b.start = std::min(std::max(x.parameters[j].value, b.lower), b.upper);
      out.push_back({d->id, i, j, b});
    }
  }
  return out;
}

void setExpressionValues(MauchCylinderParams& p, const std::vector<ExpressionSlot>& slots, const Eigen::VectorXd& v) {
  for (std::size_t k = 0; k < slots.size(); ++k)
    p.effects.expressions[slots[k].expression].parameters[slots[k].parameter].value = v(static_cast<Eigen::Index>(k));
}

// The parameters of the users' expressions at `slots` of `params` (written there), fitted
// within their bounds with the coefficients projected out at the model's switch constants.
BoundedFitResult fitExpressions(MauchCylinderParams& params, const std::vector<ExpressionSlot>& slots,
                                const std::vector<BenchData>& train) {
  std::vector<BoundedParameter> bounds;
  for (const auto& s : slots) bounds.push_back(s.bounds);
  // Variable projection (Golub & Pereyra 1973): at each trial of the expressions'
  // parameters the coefficients are the regression's on what the expressions leave, at the
  // model's switch constants.
  const ResidualFunction residual = [&](const Eigen::VectorXd& v) {
    MauchCylinderParams q = params;
    setExpressionValues(q, slots, v);
    Eigen::MatrixXd X;
    Eigen::VectorXd y;
    buildRegression(q, train, X, y);
    const LinearFit f = fitLeastSquares(X, y);
    return Eigen::VectorXd(y - X * Eigen::Map<const Eigen::VectorXd>(f.coefficients.data(), X.cols()));
  };
  BoundedFitResult r = solveBoundedLeastSquares(residual, bounds);
  setExpressionValues(params, slots, r.x);
  return r;
}

}  // namespace

PlantFit CylinderPlant::fit(const PlantModel& model) const {
  // With fit_switches, every candidate refits the switch widths and xhy too (a polish from
  // the baseline's multi-start fit): a hidden effect bends them, and the candidate that
  // explains it should get them back. After a joint refit (refitAccepted) they stay free,
  // and so does the latch rate after switch_delay.
  const CylinderModel& m = asCylinderModel(model);
  CylinderFitOptions options;
  options.fitSwitches = fitSwitches_ || m.switchesFree;
  options.fitLatchRate = m.latchFree;
  options.multiStart = false;
  // A user's expression: its parameters first, at the model's switch constants; then the
  // coefficients (and the switch constants the options free) at those parameters.
  MauchCylinderParams params = m.params;
  const std::vector<ExpressionSlot> slots = findExpressionSlots(params);
  BoundedFitResult expressions;
  if (!slots.empty()) expressions = fitExpressions(params, slots, train_);
  const CylinderFit fitted = fitCylinder(params, train_, options);
  PlantFit s = summarize(fitted);
  s.model = std::make_shared<CylinderModel>(fitted.params, m.switchesFree, m.latchFree);
  if (m.switchesFree) s.baseParameters = freedSwitchConstants(fitted);
  for (std::size_t k = 0; k < slots.size(); ++k) {
    if (s.effectErrors.empty() || s.effectErrors.back().first != slots[k].effect)
      s.effectErrors.emplace_back(slots[k].effect, std::vector<double>{});
    const auto i = static_cast<Eigen::Index>(k);
    s.effectErrors.back().second.push_back(i < expressions.standardErrors.size() ? expressions.standardErrors(i) : NAN);
  }
  return s;
}

PlantFit CylinderPlant::summarize(const CylinderFit& fitted) const {
  PlantFit s;
  s.model = std::make_shared<CylinderModel>(fitted.params);
  const MauchCylinder cyl(fitted.params);
  for (const auto& d : train_) {
    std::vector<int> phase;
    s.trainResidual.push_back(residualOf(cyl, d, &phase));
    s.trainPhase.push_back(phase);
    for (double r : s.trainResidual.back()) s.rss += r * r;
    s.samples += d.force.size();
  }
  s.likelihoodResidual = s.trainResidual;
  s.trainRmse = std::sqrt(s.rss / static_cast<double>(s.samples));
  s.notes = fitted.warnings;
  for (const auto& d : validate_) s.validationRmse.push_back(rmsOf(residualOf(cyl, d)));
  // Every fitted constant by name (an added effect's as "effect.constant", the base model's
  // without a dot) with their correlation: the engine's confound rule reads them.
  for (const auto& c : fitted.constants) {
    std::string name = c.name;
    std::replace(name.begin(), name.end(), '.', '_');
    s.parameterNames.push_back(name);
  }
  for (const auto& record : cylinderEffectRecords()) {
    if (!record.has(fitted.params)) continue;
    const EffectDescriptor& descriptor = describeEffect(record.id());
    std::vector<double> se;
    for (int col : cylinderEffectColumns(fitted.params, descriptor.id)) {
      se.push_back(fitted.regression.standardErrors[static_cast<std::size_t>(col)]);
      s.parameterNames[static_cast<std::size_t>(col)] =
          descriptor.name + "." + s.parameterNames[static_cast<std::size_t>(col)];
    }
    s.effectErrors.emplace_back(descriptor.id, se);
  }
  if (fitted.correlation.rows() == static_cast<Eigen::Index>(s.parameterNames.size())) {
    s.correlation = fitted.correlation;
  } else {
    s.parameterNames.clear();  // no correlation to go with them
  }
  return s;
}

std::string CylinderPlant::checkApplicable(const PlantModel& model, EffectId effect) const {
  return checkCylinderEffectApplicable(cylinderParams(model), effect);
}

PlantModelPtr CylinderPlant::addEffect(const PlantModel& model, EffectId effect, double gridValue) const {
  const CylinderModel& m = asCylinderModel(model);
  return std::make_shared<CylinderModel>(addCylinderEffect(m.params, effect, gridValue), m.switchesFree, m.latchFree);
}

PlantFit CylinderPlant::fitJointly(const MauchCylinderParams& params, bool fitLatchRate) const {
  CylinderFitOptions options;
  options.fitSwitches = true;
  options.fitLatchRate = fitLatchRate;
  // The projected cost is not convex in the switch constants (and a single training speed
  // leaves the latch rate in a long shallow valley): starts from the candidate's solution,
  // from it at every latch time constant of switch_delay's grid, and from the multi-start
  // grid over the physical ranges, each polished; the best is kept.
  options.multiStart = true;
  options.extraStarts = {params.switches};
  if (fitLatchRate)
    for (double tau : describeEffect(EffectId::kSwitchDelay).grid) {
      MauchSwitchParams start = params.switches;
      start.latchRate = 1.0 / tau;
      options.extraStarts.push_back(start);
    }
  CylinderFit best = fitCylinder(params, train_, options);
  // Polished on from there while it still falls (a multi-start polish may stop at its
  // budget in a flat valley): else the next step's candidates, each polished again, would
  // all gain from the polish rather than from their effect.
  options.multiStart = false;
  options.extraStarts.clear();
  for (int pass = 0; pass < kRefitPolishes; ++pass) {
    CylinderFit next = fitCylinder(best.params, train_, options);
    const bool falls = next.regression.residualRms < best.regression.residualRms * (1.0 - kRefitPolishFall);
    if (next.regression.residualRms < best.regression.residualRms) best = std::move(next);
    if (!falls) break;
  }
  PlantFit s = summarize(best);
  s.model = std::make_shared<CylinderModel>(best.params, true, fitLatchRate);
  s.baseParameters = freedSwitchConstants(best);
  return s;
}

PlantFit CylinderPlant::refitAccepted(const PlantFit& candidate, EffectId effect) const {
  const CylinderEffectRecord& record = findCylinderEffectRecord(effect);
  if (record.refit == CylinderRefit::kNone) return candidate;
  const CylinderModel& m = asCylinderModel(*candidate.model);
  const bool latch = m.latchFree || record.refit == CylinderRefit::kSwitchesLatch;
  PlantFit out = fitJointly(m.params, latch);
  if (const auto nesting = record.nestingModel ? record.nestingModel(m.params) : std::nullopt) {
    try {
      PlantFit split = fitJointly(*nesting, latch);
      if (supportsSplit(out, split)) out = std::move(split);
    } catch (const RunError&) {
      // A phase of the split the training data never enter: the merged model stays.
    }
  }
  // The joint fit starts from the candidate's solution, so it is never worse than the
  // candidate unless a polish stopped early: then the candidate stays.
  return out.rss <= candidate.rss ? out : candidate;
}

std::optional<double> CylinderPlant::calcHeldParameterRss(const PlantModel& fitted, const std::string& parameter,
                                                          double value) const {
  const CylinderModel& m = asCylinderModel(fitted);
  if (!m.switchesFree) return std::nullopt;
  MauchCylinderParams p = m.params;
  CylinderFitOptions options;
  options.fitSwitches = true;
  options.fitLatchRate = m.latchFree;
  options.multiStart = false;
  // Held: its range shrunk to the value (relative 1e-9, so the bounded solver keeps a box).
  auto hold = [&](double& field, double range[2]) {
    field = value;
    const double eps = 1e-9 * std::max(std::abs(value), 1e-9);
    range[0] = value - eps;
    range[1] = value + eps;
  };
  SwitchConstantRanges& r = options.ranges;
  if (parameter == "velocity_width_m_per_s")
    hold(p.switches.velocityWidth, r.velocityWidth);
  else if (parameter == "position_width_m")
    hold(p.switches.positionWidth, r.positionWidth);
  else if (parameter == "hyperextension_position_m")
    hold(p.switches.hyperextensionPosition, r.hyperextension);
  else if (parameter == "latch_rate_per_s" && m.latchFree)
    hold(p.switches.latchRate, r.latchRate);
  else
    return std::nullopt;
  return summarize(fitCylinder(p, train_, options)).rss;
}

PlantModelPtr CylinderPlant::combine(const PlantModel& a, const PlantModel& b, EffectId effectOfB) const {
  const CylinderModel& ma = asCylinderModel(a);
  const CylinderModel& mb = asCylinderModel(b);
  MauchCylinderParams p = ma.params;
  const CylinderEffectRecord& record = findCylinderEffectRecord(effectOfB);
  if (record.combine)
    record.combine(p, mb.params);
  else
    record.add(p, 0.0);
  return std::make_shared<CylinderModel>(p, ma.switchesFree || mb.switchesFree, ma.latchFree || mb.latchFree);
}

std::vector<double> CylinderPlant::effectValues(const PlantModel& model, EffectId effect) const {
  return findCylinderEffectRecord(effect).values(cylinderParams(model));
}

bool CylinderPlant::checkPhysical(const PlantModel& model, EffectId effect, std::string& note) const {
  return findCylinderEffectRecord(effect).isPhysical(cylinderParams(model), train_, note);
}

std::vector<std::string> CylinderPlant::phaseNames(const PlantModel& model) const {
  return cylinderPhaseNames(cylinderParams(model));
}

Comparison CylinderPlant::compare(const PlantModel& model) const {
  const MauchCylinderParams& params = cylinderParams(model);
  Comparison out;
  out.quantity = "force";
  out.unit = "N";
  out.phaseNames = cylinderPhaseNames(params);
  out.plotSeconds = plotSeconds_;
  const MauchCylinder cyl(params);
  auto run = [&](const BenchData& d, bool training) {
    RecordComparison rc;
    rc.stem = d.stem;
    rc.training = training;
    rc.time = d.time;
    rc.measured = d.force;
    const CylinderTrace tr = calcCylinderTrace(cyl, d.time, d.position, d.velocity, 0.0);
    rc.predicted = tr.force;
    rc.phase.resize(d.force.size());
    for (std::size_t i = 0; i < d.force.size(); ++i)
      rc.phase[i] = static_cast<int>(std::max_element(tr.gates[i].begin(), tr.gates[i].end()) - tr.gates[i].begin());
    std::vector<double> mm, mmPerS;
    for (double x : d.position) mm.push_back(1e3 * x);
    for (double x : d.velocity) mmPerS.push_back(1e3 * x);
    rc.variables = {{"piston position (mm)", "", mm},
                    {"piston velocity (mm/s)", "", mmPerS},
                    {"piston acceleration (m/s^2)", "", estimatePistonVelocity(d.time, d.velocity)}};
    finishRecordComparison(rc, out.phaseNames.size());
    out.records.push_back(std::move(rc));
  };
  for (const auto& d : train_) run(d, true);
  for (const auto& d : validate_) run(d, false);
  return out;
}

std::vector<std::string> CylinderPlant::validationStems() const {
  std::vector<std::string> stems;
  for (const auto& d : validate_) stems.push_back(d.stem);
  return stems;
}

std::optional<MissingForce> CylinderPlant::calcMissingForce(const PlantModel& model) const {
  std::vector<BenchData> records = train_;
  records.insert(records.end(), validate_.begin(), validate_.end());
  std::vector<double> noise;
  for (const auto& n : estimateRecordNoise()) noise.push_back(n.sigma);
  return swingsim::calcMissingForce(cylinderParams(model), records, noise);
}

std::vector<std::string> CylinderPlant::recordStems() const {
  std::vector<std::string> stems;
  for (const auto* records : {&train_, &validate_})
    for (const auto& d : *records) stems.push_back(d.stem);
  return stems;
}

std::unique_ptr<DiagnosisPlant> CylinderPlant::withOnlyRecord(std::size_t index) const {
  if (index >= train_.size() + validate_.size()) return nullptr;
  const BenchData& d = index < train_.size() ? train_[index] : validate_[index - train_.size()];
  return std::make_unique<CylinderPlant>(start_, std::vector<BenchData>{d}, std::vector<BenchData>{}, false,
                                         plotSeconds_);
}

std::vector<NoiseEstimate> CylinderPlant::estimateRecordNoise() const {
  std::vector<NoiseEstimate> out;
  for (const auto* records : {&train_, &validate_})
    for (const auto& d : *records) out.push_back(estimateNoise(d.time, d.force));
  return out;
}

}  // namespace swingsim
