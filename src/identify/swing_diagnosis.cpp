#include "identify/swing_diagnosis.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>

#include "core/input_error.h"
#include "knee/knee_friction.h"
#include "swing/knee_setup.h"
#include "swing/reference_swing.h"

namespace swingsim {

namespace {

// chi^2(1) 95 % quantile, for the profile-likelihood interval of the friction smoothing.
constexpr double kChi2One95 = 3.841458820694124;
// Levenberg-Marquardt: forward-difference step relative to a parameter's typical size (the
// reference integrator at 1e-9 is smooth to ~1e-9 rad, so the derivative error is ~1e-4).
constexpr double kDifferenceStep = 1e-5;
constexpr int kMaxIterations = 40;
constexpr double kCostTolerance = 1e-9;  // relative cost fall that ends the iterations

std::string fmt(double v, const char* f = "%.3g") {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

}  // namespace


const std::vector<SwingEffectInfo>& swingEffectLibrary() {
  static const std::vector<SwingEffectInfo> lib = {
      {"knee_coulomb_friction",
       "a friction moment of constant size that opposes knee motion over the whole range (not only below 4 deg like Tc)",
       "Burkett 2004 applies friction Tc only near extension; bearings and seals rub everywhere",
       "swings at several speeds (friction does not grow with knee speed)", false},
      {"knee_viscous_damping",
       "extra knee damping proportional to knee speed (a stiffer hydraulic setting than the model's)",
       "swing-phase control knees resist in proportion to speed; the damping table is an assumption",
       "swings at several speeds (damping grows with knee speed)", false},
      {"extension_assist_spring",
       "a spring that pulls the knee towards extension, as many prosthetic knees have",
       "extension assist springs are a common prosthetic knee feature, absent from the model",
       "swings with different peak knee flexion (the spring grows with the angle)", false},
      {"toe_off_velocity",
       "the hip and knee already move at toe-off: energy released by the prosthetic foot",
       "Burkett 2004 assumed zero velocities at toe-off and names the foot's energy as future work",
       "swings with different initial conditions, or a measured toe-off velocity", true},
      {"hip_moment_scale",
       "the hip moment that really drives the swing is larger or smaller than the measured one (calibration)",
       "the hip moment comes from a dynamometer or inverse dynamics, both with gain errors",
       "a measured hip moment with independent calibration, or swings with different hip effort", true},
      {"shank_mass_scale",
       "the shank is heavier or lighter than the model's (mass and inertia scaled together)",
       "segment masses come from a table (Burkett 2004 Table 2) and change with the prosthesis build",
       "weighing the shank, or swings with an added mass (Bach 1994)", true},
  };
  return lib;
}

const SwingEffectInfo& findSwingEffect(const std::string& name) {
  for (const auto& e : swingEffectLibrary())
    if (e.name == name) return e;
  throw std::invalid_argument("unknown swing effect '" + name + "'");
}

const std::vector<double>& kneeFrictionSmoothingGrid() {
  static const std::vector<double> g = {0.5, 1.0, 2.0, 5.0};
  return g;
}

bool SwingEffects::has(const std::string& e) const {
  if (e == "knee_coulomb_friction") return coulomb;
  if (e == "knee_viscous_damping") return viscous;
  if (e == "extension_assist_spring") return assist;
  if (e == "toe_off_velocity") return toeOff;
  if (e == "hip_moment_scale") return hipScale;
  if (e == "shank_mass_scale") return shankScale;
  throw std::invalid_argument("unknown swing effect '" + e + "'");
}

SwingModelParams addSwingEffect(const SwingModelParams& params, const std::string& effect, double nonlinear) {
  SwingModelParams p = params;
  auto& e = p.effects;
  if (effect == "knee_coulomb_friction") {
    e.coulomb = true;
    e.knee.coulombMoment = 0;
    e.knee.coulombSmoothingRate = nonlinear;
  } else if (effect == "knee_viscous_damping") {
    e.viscous = true;
    e.knee.viscousDamping = 0;
  } else if (effect == "extension_assist_spring") {
    e.assist = true;
    e.knee.assistStiffness = 0;
  } else if (effect == "toe_off_velocity") {
    e.toeOff = true;
    e.toeOffHipRate = e.toeOffKneeRate = 0;
  } else if (effect == "hip_moment_scale") {
    e.hipScale = true;
    e.hipMomentScale = 1;
  } else if (effect == "shank_mass_scale") {
    e.shankScale = true;
    e.shankMassScale = 1;
  } else {
    throw std::invalid_argument("unknown swing effect '" + effect + "'");
  }
  return p;
}

std::vector<EffectParameter> getSwingEffectParameters(const SwingModelParams& p, const std::string& effect) {
  const auto& e = p.effects;
  auto one = [](const char* n, double v) { return EffectParameter{n, v, v, v}; };
  if (!e.has(effect)) return {};
  if (effect == "knee_coulomb_friction")
    return {one("moment_Nm", e.knee.coulombMoment), one("smoothing_deg_s", e.knee.coulombSmoothingRate * kRadToDeg)};
  if (effect == "knee_viscous_damping") return {one("damping_Nm_s_per_rad", e.knee.viscousDamping)};
  if (effect == "extension_assist_spring") return {one("stiffness_Nm_per_rad", e.knee.assistStiffness)};
  if (effect == "toe_off_velocity")
    return {one("hip_rate_deg_s", e.toeOffHipRate * kRadToDeg), one("knee_rate_deg_s", e.toeOffKneeRate * kRadToDeg)};
  if (effect == "hip_moment_scale") return {one("scale", e.hipMomentScale)};
  return {one("scale", e.shankMassScale)};
}

KneeLawSum makeSwingKneeLaw(const SwingBase& base, const SwingModelParams& params) {
  // The model's law: its resisting parts scaled, then added effects, its stop, then Tc.
  const KneeLawSum& model = base.knee.law;
  KneeLawSum law;
  for (std::size_t i = 0; i + 1 < model.size(); ++i)
    law.add(std::make_unique<ScaledKneeLaw>(model.part(i), params.kneeModelScale));
  if (params.effects.knee.any()) law.add(std::make_unique<KneeAddedEffects>(params.effects.knee));
  if (model.size() > 0) law.add(model.part(model.size() - 1).clone());
  KneeModel stopless;  // makeKneeLaw adds the participant's Tc
  stopless.law = law;
  return makeKneeLaw(base.participant, stopless);
}

Participant applyParticipantEffects(const Participant& participant, const SwingEffects& e) {
  Participant p = participant;
  if (e.shankScale) {
    p.shank.mass *= e.shankMassScale;
    p.shank.inertia *= e.shankMassScale;
  }
  if (e.toeOff) {
    p.initial.hipFlexionRate = e.toeOffHipRate;
    p.initial.kneeFlexionRate = e.toeOffKneeRate;
  }
  if (e.hipScale) {
    p.hipMoment.flexionAmplitude *= e.hipMomentScale;
    p.hipMoment.extensionAmplitude *= e.hipMomentScale;
    for (double& m : p.hipMoment.moments) m *= e.hipMomentScale;
  }
  return p;
}

SwingPrediction predictSwing(const SwingBase& base, const SwingModelParams& params, const SwingRecord& record,
                             double hipPose, double kneePose, double tolerance) {
  const auto& e = params.effects;
  const Participant participant = applyParticipantEffects(base.participant, e);
  const LegGeometry geometry = calcLegGeometry(participant, 0.0);
  HipMomentProfile drive;
  drive.kind = HipMomentProfile::Kind::kTable;
  drive.times = record.time;
  drive.moments = record.hipMoment;
  if (e.hipScale)
    for (double& m : drive.moments) m *= e.hipMomentScale;
  InitialConditions initial;
  initial.hipFlexion = hipPose;
  initial.kneeFlexion = kneePose;
  initial.hipFlexionRate = e.toeOff ? e.toeOffHipRate : 0.0;
  initial.kneeFlexionRate = e.toeOff ? e.toeOffKneeRate : 0.0;
  const KneeLawSum law = makeSwingKneeLaw(base, params);
  const ReferenceSwing swing(geometry, law, drive, participant.hipRange);
  ReferenceTrajectory tr;
  try {
    tr = swing.integrate(initial, record.time, tolerance, tolerance);
  } catch (const std::runtime_error& ex) {
    throw RunError(std::string("swing model along ") + record.stem + ": " + ex.what());
  }
  return {tr.hipFlexion, tr.kneeFlexion, tr.kneeFlexionRate};
}

std::vector<std::string> swingPhaseNames() { return {"early flexion", "late extension", "terminal/stop contact"}; }

namespace {

// ---- The free parameters as one vector ------------------------------------------------
struct Slot {
  std::string effect;  // "" for the base model's knee scale
  double typical;
  std::function<double&(SwingModelParams&)> ref;
};

std::vector<Slot> slotsOf(const SwingEffects& e) {
  std::vector<Slot> s;
  s.push_back({"", 1.0, [](SwingModelParams& p) -> double& { return p.kneeModelScale; }});
  if (e.coulomb) s.push_back({"knee_coulomb_friction", 1.0, [](SwingModelParams& p) -> double& { return p.effects.knee.coulombMoment; }});
  if (e.viscous) s.push_back({"knee_viscous_damping", 0.5, [](SwingModelParams& p) -> double& { return p.effects.knee.viscousDamping; }});
  if (e.assist) s.push_back({"extension_assist_spring", 5.0, [](SwingModelParams& p) -> double& { return p.effects.knee.assistStiffness; }});
  if (e.toeOff) {
    s.push_back({"toe_off_velocity", 1.0, [](SwingModelParams& p) -> double& { return p.effects.toeOffHipRate; }});
    s.push_back({"toe_off_velocity", 1.0, [](SwingModelParams& p) -> double& { return p.effects.toeOffKneeRate; }});
  }
  if (e.hipScale) s.push_back({"hip_moment_scale", 1.0, [](SwingModelParams& p) -> double& { return p.effects.hipMomentScale; }});
  if (e.shankScale) s.push_back({"shank_mass_scale", 1.0, [](SwingModelParams& p) -> double& { return p.effects.shankMassScale; }});
  return s;
}

// ---- Levenberg-Marquardt with forward-difference Jacobian ------------------------------
struct LmResult {
  Eigen::VectorXd x;
  Eigen::VectorXd residual;
  Eigen::MatrixXd jacobian;
  double cost = 0;
};

using ResidualFn = std::function<Eigen::VectorXd(const Eigen::VectorXd&)>;

LmResult levenbergMarquardt(const ResidualFn& f, Eigen::VectorXd x, const Eigen::VectorXd& typical) {
  LmResult out;
  out.residual = f(x);
  out.cost = out.residual.squaredNorm();
  double lambda = 1e-3;
  const Eigen::Index n = x.size();
  for (int iter = 0; iter < kMaxIterations; ++iter) {
    Eigen::MatrixXd J(out.residual.size(), n);
    for (Eigen::Index j = 0; j < n; ++j) {
      Eigen::VectorXd xh = x;
      const double h = kDifferenceStep * std::max(std::abs(x[j]), typical[j]);
      xh[j] += h;
      J.col(j) = (f(xh) - out.residual) / h;
    }
    out.jacobian = J;
    const Eigen::MatrixXd JtJ = J.transpose() * J;
    const Eigen::VectorXd g = J.transpose() * out.residual;
    bool improved = false;
    double fall = 0;
    for (int tries = 0; tries < 12 && !improved; ++tries) {
      Eigen::MatrixXd A = JtJ;
      for (Eigen::Index k = 0; k < n; ++k) A(k, k) += lambda * std::max(JtJ(k, k), 1e-12);
      const Eigen::VectorXd step = A.ldlt().solve(-g);
      const Eigen::VectorXd trial = x + step;
      Eigen::VectorXd r;
      double cost = std::numeric_limits<double>::infinity();
      try {
        r = f(trial);
        cost = r.squaredNorm();
      } catch (const RunError&) {
      }
      if (std::isfinite(cost) && cost < out.cost) {
        fall = (out.cost - cost) / std::max(out.cost, 1e-300);
        x = trial;
        out.residual = r;
        out.cost = cost;
        lambda = std::max(lambda / 3, 1e-9);
        improved = true;
      } else {
        lambda *= 4;
      }
    }
    if (!improved || fall < kCostTolerance) break;
  }
  out.x = x;
  return out;
}

// ---- One model fitted to the training files and run along all files ---------------------
struct Scored {
  SwingModelParams params;
  ResidualSegments trainResidual;   // knee and hip of every training file, deg
  double trainRss = 0;              // deg^2, both angles
  double trainKneeRss = 0;
  std::size_t trainSamples = 0, trainKneeSamples = 0;
  std::vector<double> validationRmse;  // knee, deg
  Eigen::MatrixXd covariance;          // of the global parameters, from the Jacobian
  std::vector<std::vector<int>> trainPhase;
  std::vector<std::vector<double>> trainKneeResidual;
};

std::vector<int> phasesOf(const std::vector<double>& knee, double zone) {
  std::vector<int> ph(knee.size(), 0);
  const std::size_t peak = static_cast<std::size_t>(std::max_element(knee.begin(), knee.end()) - knee.begin());
  int current = 0;
  for (std::size_t i = 0; i < knee.size(); ++i) {
    if (i > peak && current == 0) current = 1;
    if (current == 1 && knee[i] < zone) current = 2;
    ph[i] = current;
  }
  return ph;
}

struct PoseFit {
  double hip = 0, knee = 0;
  SwingPrediction prediction;
};

// The toe-off pose of one record with the model frozen (validation, compare).
PoseFit fitPose(const SwingBase& base, const SwingModelParams& params, const SwingRecord& r, double tol) {
  const double tolDeg = kRadToDeg;
  ResidualFn f = [&](const Eigen::VectorXd& x) {
    const SwingPrediction p = predictSwing(base, params, r, x[0], x[1], tol);
    Eigen::VectorXd res(2 * static_cast<Eigen::Index>(r.time.size()));
    for (std::size_t i = 0; i < r.time.size(); ++i) {
      res[static_cast<Eigen::Index>(2 * i)] = (r.kneeFlexion[i] - p.kneeFlexion[i]) * tolDeg;
      res[static_cast<Eigen::Index>(2 * i + 1)] = (r.hipFlexion[i] - p.hipFlexion[i]) * tolDeg;
    }
    return res;
  };
  Eigen::VectorXd x0(2), typ(2);
  x0 << r.hipFlexion.front(), r.kneeFlexion.front();
  typ << 0.1, 0.1;
  const LmResult lm = levenbergMarquardt(f, x0, typ);
  PoseFit out;
  out.hip = lm.x[0];
  out.knee = lm.x[1];
  out.prediction = predictSwing(base, params, r, out.hip, out.knee, tol);
  return out;
}

double kneeRmse(const SwingRecord& r, const SwingPrediction& p) {
  double s = 0;
  for (std::size_t i = 0; i < r.time.size(); ++i) s += std::pow((r.kneeFlexion[i] - p.kneeFlexion[i]) * kRadToDeg, 2);
  return std::sqrt(s / static_cast<double>(r.time.size()));
}

Scored fitAndScore(const SwingBase& base, const SwingModelParams& start, const std::vector<SwingRecord>& train,
                   const std::vector<SwingRecord>& validate, double tol) {
  const std::vector<Slot> slots = slotsOf(start.effects);
  const Eigen::Index g = static_cast<Eigen::Index>(slots.size());
  const Eigen::Index n = g + 2 * static_cast<Eigen::Index>(train.size());
  Eigen::VectorXd x0(n), typ(n);
  SwingModelParams p0 = start;
  for (Eigen::Index k = 0; k < g; ++k) {
    x0[k] = slots[static_cast<std::size_t>(k)].ref(p0);
    typ[k] = slots[static_cast<std::size_t>(k)].typical;
  }
  for (std::size_t f = 0; f < train.size(); ++f) {
    x0[g + 2 * static_cast<Eigen::Index>(f)] = train[f].hipFlexion.front();
    x0[g + 2 * static_cast<Eigen::Index>(f) + 1] = train[f].kneeFlexion.front();
    typ[g + 2 * static_cast<Eigen::Index>(f)] = typ[g + 2 * static_cast<Eigen::Index>(f) + 1] = 0.1;
  }
  auto paramsAt = [&](const Eigen::VectorXd& x) {
    SwingModelParams p = start;
    for (Eigen::Index k = 0; k < g; ++k) slots[static_cast<std::size_t>(k)].ref(p) = x[k];
    return p;
  };
  std::size_t rows = 0;
  for (const auto& r : train) rows += 2 * r.time.size();
  ResidualFn fn = [&](const Eigen::VectorXd& x) {
    const SwingModelParams p = paramsAt(x);
    Eigen::VectorXd res(static_cast<Eigen::Index>(rows));
    Eigen::Index row = 0;
    for (std::size_t f = 0; f < train.size(); ++f) {
      const auto& r = train[f];
      const SwingPrediction pr = predictSwing(base, p, r, x[g + 2 * static_cast<Eigen::Index>(f)],
                                              x[g + 2 * static_cast<Eigen::Index>(f) + 1], tol);
      for (std::size_t i = 0; i < r.time.size(); ++i) {
        res[row++] = (r.kneeFlexion[i] - pr.kneeFlexion[i]) * kRadToDeg;
        res[row++] = (r.hipFlexion[i] - pr.hipFlexion[i]) * kRadToDeg;
      }
    }
    return res;
  };
  const LmResult lm = levenbergMarquardt(fn, x0, typ);
  Scored s;
  s.params = paramsAt(lm.x);
  s.trainRss = lm.cost;
  Eigen::Index row = 0;
  for (std::size_t f = 0; f < train.size(); ++f) {
    std::vector<double> knee, hip;
    for (std::size_t i = 0; i < train[f].time.size(); ++i) {
      knee.push_back(lm.residual[row++]);
      hip.push_back(lm.residual[row++]);
      s.trainKneeRss += knee.back() * knee.back();
    }
    s.trainKneeSamples += knee.size();
    s.trainSamples += knee.size() + hip.size();
    // Phases from the fitted model's knee (measured minus residual).
    std::vector<double> modelKnee;
    for (std::size_t i = 0; i < knee.size(); ++i) modelKnee.push_back(train[f].kneeFlexion[i] - knee[i] * kDegToRad);
    s.trainPhase.push_back(phasesOf(modelKnee, base.participant.swingEnd.zoneOfStability));
    s.trainKneeResidual.push_back(knee);
    s.trainResidual.push_back(knee);
    s.trainResidual.push_back(hip);
  }
  const double dofResidual = std::max(1.0, static_cast<double>(rows) - static_cast<double>(n));
  const Eigen::MatrixXd JtJ = lm.jacobian.transpose() * lm.jacobian;
  s.covariance = (lm.cost / dofResidual) * JtJ.completeOrthogonalDecomposition().pseudoInverse();
  for (const auto& r : validate) s.validationRmse.push_back(kneeRmse(r, fitPose(base, s.params, r, tol).prediction));
  return s;
}

// Standard error of every global slot of `effect` (in slot order).
std::vector<double> slotErrors(const Scored& s, const std::string& effect) {
  const auto slots = slotsOf(s.params.effects);
  std::vector<double> se;
  for (std::size_t k = 0; k < slots.size(); ++k)
    if (slots[k].effect == effect) se.push_back(std::sqrt(std::max(0.0, s.covariance(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(k)))));
  return se;
}

int linearCount(const std::string& effect) { return effect == "toe_off_velocity" ? 2 : 1; }

std::vector<double> gridOf(const std::string& effect) {
  return effect == "knee_coulomb_friction" ? kneeFrictionSmoothingGrid() : std::vector<double>{0.0};
}

std::string physicalCheck(const SwingModelParams& p, const std::string& effect, bool& ok) {
  const auto& e = p.effects;
  if (effect == "knee_coulomb_friction") {
    ok = e.knee.coulombMoment > 0;
    return "friction must oppose knee motion (moment_Nm > 0): " + fmt(e.knee.coulombMoment) + " N m";
  }
  if (effect == "knee_viscous_damping") {
    ok = e.knee.viscousDamping > 0;
    return "a passive damper must resist knee motion (> 0): " + fmt(e.knee.viscousDamping) + " N m s/rad";
  }
  if (effect == "extension_assist_spring") {
    ok = e.knee.assistStiffness > 0;
    return "the spring must pull towards extension (stiffness > 0): " + fmt(e.knee.assistStiffness) + " N m/rad";
  }
  if (effect == "toe_off_velocity") {
    ok = e.toeOffKneeRate > 0;
    return "energy released by the foot must flex the knee (knee rate > 0): " + fmt(e.toeOffKneeRate * kRadToDeg) +
           " deg/s";
  }
  if (effect == "hip_moment_scale") {
    ok = e.hipMomentScale > 0;
    return "a gain error cannot reverse the moment (scale > 0): " + fmt(e.hipMomentScale);
  }
  ok = e.shankMassScale > 0;
  return "mass must stay positive (scale > 0): " + fmt(e.shankMassScale);
}

std::string applicability(const SwingModelParams& p, const std::string& effect) {
  return p.effects.has(effect) ? "already in the model" : "";
}

SwingCandidateScore scoreCandidate(const SwingBase& base, const Scored& current, const std::string& effect,
                                   const std::vector<SwingRecord>& train, const std::vector<SwingRecord>& validate,
                                   const SwingDiagnosisSettings& settings, Scored* bestOut) {
  SwingCandidateScore c;
  c.effect = effect;
  c.notApplicable = applicability(current.params, effect);
  if (!c.notApplicable.empty()) return c;
  const auto grid = gridOf(effect);
  std::vector<Scored> fits;
  std::size_t best = 0;
  for (double gv : grid) {
    try {
      fits.push_back(fitAndScore(base, addSwingEffect(current.params, effect, gv), train, validate,
                                 settings.integratorTolerance));
    } catch (const RunError& e) {
      c.notApplicable = e.what();
      return c;
    }
    if (fits.back().trainRss < fits[best].trainRss) best = fits.size() - 1;
  }
  const Scored& s = fits[best];
  const int dof = linearCount(effect) + (grid.size() > 1 ? 1 : 0);
  const LrTest t = calcLrTest(current.trainRss, s.trainRss, s.trainResidual, dof);
  c.params = s.params;
  c.trainRmse = std::sqrt(s.trainKneeRss / static_cast<double>(s.trainKneeSamples));
  c.validationRmse = s.validationRmse;
  applyTestAndValidation(c, t, dof, current.validationRmse, settings);
  c.parameters = getSwingEffectParameters(s.params, effect);
  const auto se = slotErrors(s, effect);
  const double inflate = calcStandardErrorInflation(static_cast<double>(s.trainSamples), t.nEff);
  // Rates are reported in deg/s, the slots hold rad/s.
  const double unit = effect == "toe_off_velocity" ? kRadToDeg : 1.0;
  for (std::size_t k = 0; k < se.size() && k < c.parameters.size(); ++k) setNormalInterval(c.parameters[k], se[k] * inflate * unit);
  if (grid.size() > 1) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (std::size_t gi = 0; gi < grid.size(); ++gi)
      if (t.nEff * std::log(fits[gi].trainRss / s.trainRss) <= kChi2One95) {
        lo = std::min(lo, grid[gi] * kRadToDeg);
        hi = std::max(hi, grid[gi] * kRadToDeg);
      }
    c.parameters.back().lower = lo;
    c.parameters.back().upper = hi;
    // The moment's interval is conditional on the smoothing: take the union over every grid
    // value inside the smoothing's profile interval (the grid choice must not narrow it).
    for (std::size_t gi = 0; gi < grid.size(); ++gi) {
      if (!(t.nEff * std::log(fits[gi].trainRss / s.trainRss) <= kChi2One95)) continue;
      auto others = getSwingEffectParameters(fits[gi].params, effect);
      const auto seOther = slotErrors(fits[gi], effect);
      for (std::size_t k = 0; k < seOther.size() && k + 1 < c.parameters.size(); ++k) {
        setNormalInterval(others[k], seOther[k] * inflate * unit);
        c.parameters[k].lower = std::min(c.parameters[k].lower, others[k].lower);
        c.parameters[k].upper = std::max(c.parameters[k].upper, others[k].upper);
      }
    }
  }
  c.physicalNote = physicalCheck(s.params, effect, c.physical);
  c.physicalNote += c.physical ? " (ok)" : " (wrong sign)";
  const auto names = swingPhaseNames();
  std::vector<double> fall(names.size(), 0.0);
  double totalFall = 0;
  for (std::size_t f = 0; f < train.size(); ++f)
    for (std::size_t i = 0; i < current.trainKneeResidual[f].size(); ++i) {
      const double d = std::pow(current.trainKneeResidual[f][i], 2) - std::pow(s.trainKneeResidual[f][i], 2);
      fall[static_cast<std::size_t>(current.trainPhase[f][i])] += d;
      totalFall += d;
    }
  const auto where = static_cast<std::size_t>(std::max_element(fall.begin(), fall.end()) - fall.begin());
  c.where = names[where] + (totalFall > 0 ? " (" + fmt(100.0 * fall[where] / totalFall, "%.0f") + " % of the knee error fall)" : "");
  for (const auto& r : s.trainKneeResidual) c.trainResidual.insert(c.trainResidual.end(), r.begin(), r.end());
  if (bestOut) *bestOut = s;
  return c;
}

// Both effects of two fitted candidates in one model, values as fitted.
SwingModelParams combine(const SwingModelParams& a, const SwingModelParams& b, const std::string& effectOfB) {
  SwingModelParams p = a;
  auto& e = p.effects;
  const auto& f = b.effects;
  if (effectOfB == "knee_coulomb_friction") {
    e.coulomb = true;
    e.knee.coulombMoment = f.knee.coulombMoment;
    e.knee.coulombSmoothingRate = f.knee.coulombSmoothingRate;
  } else if (effectOfB == "knee_viscous_damping") {
    e.viscous = true;
    e.knee.viscousDamping = f.knee.viscousDamping;
  } else if (effectOfB == "extension_assist_spring") {
    e.assist = true;
    e.knee.assistStiffness = f.knee.assistStiffness;
  } else if (effectOfB == "toe_off_velocity") {
    e.toeOff = true;
    e.toeOffHipRate = f.toeOffHipRate;
    e.toeOffKneeRate = f.toeOffKneeRate;
  } else if (effectOfB == "hip_moment_scale") {
    e.hipScale = true;
    e.hipMomentScale = f.hipMomentScale;
  } else if (effectOfB == "shank_mass_scale") {
    e.shankScale = true;
    e.shankMassScale = f.shankMassScale;
  }
  return p;
}

std::string describeStructure(const SwingComparison& cmp, double nEffRatio) {
  std::string out;
  double bestExcess = -1;
  const auto& rc = cmp.records.front();
  for (std::size_t ph = 0; ph < cmp.phaseNames.size(); ++ph) {
    const double excess = rc.phaseShare[ph] - rc.sampleShare[ph];
    if (excess > bestExcess) {
      bestExcess = excess;
      out = "the largest share of squared knee error is in " + cmp.phaseNames[ph] + " (" +
            fmt(100 * rc.phaseShare[ph], "%.0f") + " % of the error in " + fmt(100 * rc.sampleShare[ph], "%.0f") +
            " % of the samples)";
    }
  }
  std::vector<double> angle, rate, r;
  for (const auto& c : cmp.records) {
    if (!c.training) continue;
    for (double v : c.predictedKnee) angle.push_back(v * kRadToDeg);
    rate.insert(rate.end(), c.kneeRate.begin(), c.kneeRate.end());
    r.insert(r.end(), c.kneeResidual.begin(), c.kneeResidual.end());
  }
  double best = 0;
  std::string binNote;
  const std::pair<const char*, const std::vector<double>*> vars[] = {{"knee flexion (deg)", &angle},
                                                                     {"knee flexion rate (deg/s)", &rate}};
  for (const auto& [name, values] : vars) {
    const BinnedResidual b = calcBinnedResidual(*values, r, 12, nEffRatio);
    if (b.maxSignificance > best && !b.center.empty()) {
      best = b.maxSignificance;
      binNote = "; the binned mean knee residual departs most from zero at " + std::string(name) + " " +
                fmt(b.center[b.maxBin]) + " (mean " + fmt(b.mean[b.maxBin]) + " deg, " + fmt(b.maxSignificance, "%.1f") +
                " x its 99 % half-width)";
    }
  }
  return out + binNote;
}

}  // namespace

SwingComparison compareSwing(const SwingBase& base, const SwingModelParams& params, const std::vector<SwingRecord>& train,
                             const std::vector<SwingRecord>& validate) {
  SwingComparison out;
  out.phaseNames = swingPhaseNames();
  const double tol = SwingDiagnosisSettings{}.integratorTolerance;
  auto run = [&](const SwingRecord& r, bool training) {
    SwingRecordComparison rc;
    rc.data = &r;
    rc.training = training;
    const PoseFit pf = fitPose(base, params, r, tol);
    rc.hipPose = pf.hip;
    rc.kneePose = pf.knee;
    rc.predictedKnee = pf.prediction.kneeFlexion;
    rc.predictedHip = pf.prediction.hipFlexion;
    for (double v : pf.prediction.kneeFlexionRate) rc.kneeRate.push_back(v * kRadToDeg);
    std::vector<double> mk, pk, mh, ph;
    for (std::size_t i = 0; i < r.time.size(); ++i) {
      mk.push_back(r.kneeFlexion[i] * kRadToDeg);
      pk.push_back(rc.predictedKnee[i] * kRadToDeg);
      mh.push_back(r.hipFlexion[i] * kRadToDeg);
      ph.push_back(rc.predictedHip[i] * kRadToDeg);
      rc.kneeResidual.push_back(mk.back() - pk.back());
      rc.hipResidual.push_back(mh.back() - ph.back());
    }
    rc.phase = phasesOf(rc.predictedKnee, base.participant.swingEnd.zoneOfStability);
    rc.knee = calcErrorMetrics(mk, pk);
    rc.hip = calcErrorMetrics(mh, ph);
    double total = 0;
    for (double v : rc.kneeResidual) total += v * v;
    for (std::size_t p = 0; p < out.phaseNames.size(); ++p) {
      std::vector<bool> mask(mk.size());
      double sq = 0;
      std::size_t count = 0;
      for (std::size_t i = 0; i < mask.size(); ++i) {
        mask[i] = rc.phase[i] == static_cast<int>(p);
        if (mask[i]) {
          sq += rc.kneeResidual[i] * rc.kneeResidual[i];
          ++count;
        }
      }
      rc.perPhase.push_back(calcErrorMetrics(mk, pk, mask));
      rc.phaseShare.push_back(total > 0 ? sq / total : 0.0);
      rc.sampleShare.push_back(static_cast<double>(count) / static_cast<double>(mask.size()));
    }
    out.records.push_back(std::move(rc));
  };
  for (const auto& r : train) run(r, true);
  for (const auto& r : validate) run(r, false);
  return out;
}

SwingDiagnosis diagnoseSwing(const SwingBase& base, const std::vector<SwingRecord>& train,
                             const std::vector<SwingRecord>& validate, const SwingDiagnosisSettings& settings) {
  if (validate.empty())
    throw InputError("diagnose: the acceptance rule needs at least one validation file (validate:)");
  if (train.empty()) throw InputError("diagnose: no training file (train:)");
  std::vector<std::string> library;
  for (const auto& e : swingEffectLibrary()) library.push_back(e.name);
  const std::vector<std::string> names = resolveCandidates(settings.candidates, library);
  const double tol = settings.integratorTolerance;

  SwingDiagnosis out;
  Scored current = fitAndScore(base, SwingModelParams{}, train, validate, tol);
  out.baseline = current.params;
  {
    const double se = std::sqrt(std::max(0.0, current.covariance(0, 0))) *
                      calcStandardErrorInflation(static_cast<double>(current.trainSamples),
                                                 calcEffectiveSampleSize(current.trainResidual));
    EffectParameter p{"", current.params.kneeModelScale, 0, 0};
    setNormalInterval(p, se);
    out.baselineScaleLower = p.lower;
    out.baselineScaleUpper = p.upper;
  }
  out.baselineWhiteness = calcWhitenessTest(current.trainResidual, settings.whitenessLags);

  for (int stepNo = 0; stepNo < settings.maxEffects; ++stepNo) {
    SwingDiagnosisStep step;
    step.currentTrainRmse = std::sqrt(current.trainKneeRss / static_cast<double>(current.trainKneeSamples));
    step.currentValidationRmse = current.validationRmse;
    std::vector<Scored> best(names.size());
    for (std::size_t i = 0; i < names.size(); ++i)
      step.candidates.push_back(scoreCandidate(base, current, names[i], train, validate, settings, &best[i]));
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
        joint = fitAndScore(base, combine(best[j].params, best[chosen].params, names[chosen]), train, validate, tol);
      } catch (const RunError&) {
        return std::nullopt;
      }
      const int dofChosen = linearCount(names[chosen]) + (gridOf(names[chosen]).size() > 1 ? 1 : 0);
      return calcLrTest(best[j].trainRss, joint.trainRss, joint.trainResidual, dofChosen).p;
    });
    current = best[chosen];
    out.accepted.push_back(names[chosen]);
    out.acceptedScores.push_back(step.candidates[chosen]);
    recordAmbiguity(step.group, [](const std::string& e) { return findSwingEffect(e).separatedBy; }, out.ambiguous,
                    out.ambiguityAdvice);
    out.steps.push_back(step);
  }
  out.final = current.params;
  out.finalWhiteness = calcWhitenessTest(current.trainResidual, settings.whitenessLags);
  out.finalResidualWhite = out.finalWhiteness.pValue >= settings.alpha;
  if (!out.finalResidualWhite) {
    const double ratio = calcEffectiveSampleSize(current.trainResidual) / static_cast<double>(current.trainSamples);
    out.structureNote = describeStructure(compareSwing(base, out.final, train, {}), ratio);
  }
  return out;
}

double calcSwingEffectRms(const SwingBase& base, const SwingModelParams& truth, const std::string& effect,
                          const SwingRecord& record) {
  SwingModelParams without = truth;
  auto& e = without.effects;
  if (effect == "knee_coulomb_friction") e.coulomb = false, e.knee.coulombMoment = 0;
  else if (effect == "knee_viscous_damping") e.viscous = false, e.knee.viscousDamping = 0;
  else if (effect == "extension_assist_spring") e.assist = false, e.knee.assistStiffness = 0;
  else if (effect == "toe_off_velocity") e.toeOff = false;
  else if (effect == "hip_moment_scale") e.hipScale = false;
  else if (effect == "shank_mass_scale") e.shankScale = false;
  else throw std::invalid_argument("unknown swing effect '" + effect + "'");
  const auto& init = base.participant.initial;
  const auto a = predictSwing(base, truth, record, init.hipFlexion, init.kneeFlexion);
  const auto b = predictSwing(base, without, record, init.hipFlexion, init.kneeFlexion);
  double s = 0;
  for (std::size_t i = 0; i < a.kneeFlexion.size(); ++i) s += std::pow((a.kneeFlexion[i] - b.kneeFlexion[i]) * kRadToDeg, 2);
  return std::sqrt(s / static_cast<double>(a.kneeFlexion.size()));
}

}  // namespace swingsim
