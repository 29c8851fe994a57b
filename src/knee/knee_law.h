#pragma once
// The one interface every knee law implements: the damping table, knee friction, the
// hyperextension stop and the Mauch hydraulic cylinder. Pure C++: no Simbody here, so
// every law can be unit-tested and fitted on its own (docs/architecture.md, layer knee/).
#include <memory>
#include <string>
#include <vector>

namespace swingsim {

/// Knee kinematics a law sees. Clinical convention: flexion positive, hyperextension
/// negative.
struct KneeKinematics {
  double flexion = 0;      ///< knee flexion angle, rad
  double flexionRate = 0;  ///< knee flexion angular velocity, rad/s
  /// The hip and the time, for a law that depends on more than the knee (a user's expression,
  /// knee/knee_expression.h); the library's laws read only the two above.
  double hipFlexion = 0;      ///< thigh from hanging straight down, forward +, rad
  double hipFlexionRate = 0;  ///< rad/s
  double time = 0;            ///< since toe-off, s
};

/// A knee moment law. `calcMoment` returns the moment the law applies about the knee, in
/// N m, positive in the flexion direction (so a law resisting flexion returns a negative
/// moment while the knee flexes). Laws may carry their own continuous states (the Mauch
/// S2 latch): the simulator integrates `calcStateDerivatives` alongside the mechanics.
class KneeLaw {
 public:
  virtual ~KneeLaw() = default;
  /// Short name for reports ("damping table", "knee friction").
  virtual std::string name() const = 0;
  /// Number of continuous states this law carries (default none).
  virtual int numStates() const { return 0; }
  /// Writes the initial values of the law's states into z[0..numStates()).
  virtual void initialStates(double* /*z*/) const {}
  /// Knee moment in N m (positive = flexion direction). `z` holds numStates() values.
  virtual double calcMoment(const KneeKinematics& knee, const double* z) const = 0;
  /// Time derivatives of the law's states, written to zdot[0..numStates()).
  virtual void calcStateDerivatives(const KneeKinematics& /*knee*/, const double* /*z*/, double* /*zdot*/) const {}
  /// Whether the law is passive: the leg's mechanical energy plus calcStoredEnergy never
  /// rises under it (a resisting moment, never of the rate's sign, stores nothing; a spring
  /// or the stop stores what it may give back). The swing stops early on this: a leg whose
  /// energy cannot lift the thigh to its target never will (simulateSwing). Default false,
  /// so a law nobody has shown to be passive (the Mauch cylinder, whose latch state could
  /// hold energy) never stops a swing early.
  virtual bool isPassive() const { return false; }
  /// Energy the law holds and may give back to the leg, J (0 for a resisting law). Only
  /// meaningful if isPassive().
  virtual double calcStoredEnergy(const KneeKinematics& /*knee*/, const double* /*z*/) const { return 0; }
  virtual std::unique_ptr<KneeLaw> clone() const = 0;
};

/// A sum of knee laws (damping + friction + stop, or cylinder + friction + stop), itself a
/// KneeLaw. States of the parts are concatenated in order.
class KneeLawSum final : public KneeLaw {
 public:
  KneeLawSum() = default;
  KneeLawSum(const KneeLawSum& other);
  KneeLawSum& operator=(const KneeLawSum& other);
  KneeLawSum(KneeLawSum&&) = default;
  KneeLawSum& operator=(KneeLawSum&&) = default;

  void add(std::unique_ptr<KneeLaw> law);
  std::size_t size() const { return laws_.size(); }
  const KneeLaw& part(std::size_t i) const { return *laws_[i]; }
  /// Moment of one part (for reports that split the knee moment by cause).
  double calcPartMoment(std::size_t i, const KneeKinematics& knee, const double* z) const;

  std::string name() const override;
  int numStates() const override;
  void initialStates(double* z) const override;
  double calcMoment(const KneeKinematics& knee, const double* z) const override;
  void calcStateDerivatives(const KneeKinematics& knee, const double* z, double* zdot) const override;
  /// Passive if it has parts and every part is.
  bool isPassive() const override;
  double calcStoredEnergy(const KneeKinematics& knee, const double* z) const override;
  std::unique_ptr<KneeLaw> clone() const override;

 private:
  std::vector<std::unique_ptr<KneeLaw>> laws_;
  std::vector<int> offsets_;  // first state index of each part
};

}  // namespace swingsim
