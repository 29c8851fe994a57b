#pragma once
// Knee moments the swing diagnosis (docs/diagnosis.md) can add to a knee model:
// Coulomb friction over the whole range (beyond the knee unit's Tc below 4 deg), extra
// viscous damping, and an extension-assist spring. Read from a knee model's
// `knee_effects:` block, so an augmented model runs in `swingsim simulate --knee`.
#include <vector>

#include "knee/knee_expression.h"
#include "knee/knee_law.h"

namespace swingsim {

struct KneeAddedEffectsParams {
  /// Coulomb friction over the whole range: -T tanh(rate / smoothingRate), N m (>= 0).
  double coulombMoment = 0;
  double coulombSmoothingRate = 1.0;  ///< rad/s, > 0
  /// Extra viscous damping: -c rate, N m s/rad (>= 0 for a passive knee).
  double viscousDamping = 0;
  /// Extension-assist spring: -k flexion, N m/rad (>= 0: pulls towards extension).
  double assistStiffness = 0;
  /// Scale on the knee model's own resisting law (the swing diagnosis refits it); applied
  /// by the loader (ScaledKneeLaw), not by this law.
  double modelScale = 1.0;
  /// Users' knee moments (knee/knee_expression.h), each its own law after these three.
  std::vector<KneeExpressionParams> expressions;
  /// Whether friction, damping or the spring acts (the expressions are laws of their own).
  bool any() const { return coulombMoment != 0 || viscousDamping != 0 || assistStiffness != 0; }
};

/// Adds one KneeExpressionMoment per expression of `params` to `law`.
void addKneeExpressionLaws(KneeLawSum& law, const KneeAddedEffectsParams& params);

/// Sum of the three added moments. Positive moment = flexion direction (KneeLaw).
/// Throws std::invalid_argument for a non-finite value or smoothingRate <= 0 (signs are the
/// diagnosis's sign rule, not checked here, so a fit may step through zero).
class KneeAddedEffects final : public KneeLaw {
 public:
  explicit KneeAddedEffects(const KneeAddedEffectsParams& params);
  const KneeAddedEffectsParams& params() const { return p_; }
  std::string name() const override { return "added knee effects"; }
  double calcMoment(const KneeKinematics& knee, const double* z) const override;
  /// Passive if the friction, the damping and the spring are not negative.
  bool isPassive() const override { return p_.coulombMoment >= 0 && p_.viscousDamping >= 0 && p_.assistStiffness >= 0; }
  /// The assist spring's k flexion^2 / 2.
  double calcStoredEnergy(const KneeKinematics& knee, const double*) const override {
    return 0.5 * p_.assistStiffness * knee.flexion * knee.flexion;
  }
  std::unique_ptr<KneeLaw> clone() const override { return std::make_unique<KneeAddedEffects>(*this); }

 private:
  KneeAddedEffectsParams p_;
};

/// A knee law multiplied by a constant (the swing diagnosis refits the knee model's
/// resistance scale, a number the user rarely knows: Burkett's damping table is an
/// assumption). Throws std::invalid_argument if the scale is not finite.
class ScaledKneeLaw final : public KneeLaw {
 public:
  ScaledKneeLaw(const KneeLaw& law, double scale);
  ScaledKneeLaw(const ScaledKneeLaw& other) : law_(other.law_->clone()), scale_(other.scale_) {}
  std::string name() const override { return law_->name(); }
  int numStates() const override { return law_->numStates(); }
  void initialStates(double* z) const override { law_->initialStates(z); }
  double calcMoment(const KneeKinematics& knee, const double* z) const override {
    return scale_ * law_->calcMoment(knee, z);
  }
  void calcStateDerivatives(const KneeKinematics& knee, const double* z, double* zdot) const override {
    law_->calcStateDerivatives(knee, z, zdot);
  }
  bool isPassive() const override { return scale_ >= 0 && law_->isPassive(); }
  double calcStoredEnergy(const KneeKinematics& knee, const double* z) const override {
    return scale_ * law_->calcStoredEnergy(knee, z);
  }
  std::unique_ptr<KneeLaw> clone() const override { return std::make_unique<ScaledKneeLaw>(*this); }

 private:
  std::unique_ptr<KneeLaw> law_;
  double scale_;
};

}  // namespace swingsim
