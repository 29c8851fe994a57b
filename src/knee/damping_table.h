#pragma once
// Dynamometer damping table (Burkett 2004, Methods: the knee's resisting moment recorded
// in passive mode while it moved from 0 to 70 deg of flexion at one dynamometer speed).
#include <vector>
#include "core/units.h"

#include "knee/knee_law.h"

namespace swingsim {

/// How a table measured at one dynamometer speed becomes a moment at other speeds.
enum class DampingSpeedRule {
  /// Viscous: moment = table(theta) * (rate / reference rate). A hydraulic or pneumatic
  /// swing-phase control behaves close to this; it is zero at rest, so no chatter.
  kLinear,
  /// Speed-independent (Coulomb-like) magnitude table(theta), direction smoothed by
  /// tanh(rate / smoothingRate).
  kConstant,
};

struct DampingTableParams {
  std::vector<double> flexion;               ///< knee flexion grid, rad, strictly increasing
  std::vector<double> moment;                ///< resisting moment magnitude at referenceRate, N m, >= 0
  double referenceRate = 150.0 * kDegToRad;  ///< rad/s
  DampingSpeedRule speedRule = DampingSpeedRule::kLinear;
  /// Extension resistance as a fraction of flexion resistance (1 = same table).
  double extensionFactor = 1.0;
  double smoothingRate = 0.5;  ///< rad/s, kConstant only
};

/// Resisting moment from a damping table: a monotone cubic in flexion (monotone_cubic.h,
/// flat ends) held constant outside the measured range. A dynamometer samples a smooth
/// curve; the C1 interpolant has no kinks at the samples, where a linear one made the
/// integrator reject steps and the swing time converge erratically with the accuracy (docs/speed.md,
/// "Convergence study"). Throws std::invalid_argument on bad parameters.
class DampingTable final : public KneeLaw {
 public:
  explicit DampingTable(DampingTableParams params);
  const DampingTableParams& params() const { return p_; }
  /// Table magnitude at a flexion angle, N m.
  double calcTableMoment(double flexion) const;

  std::string name() const override { return "damping table"; }
  double calcMoment(const KneeKinematics& knee, const double* z) const override;
  /// Passive: the moments are not negative and the extension factor is not negative (checked
  /// by the constructor), so the moment never has the rate's sign.
  bool isPassive() const override { return true; }
  std::unique_ptr<KneeLaw> clone() const override { return std::make_unique<DampingTable>(*this); }

 private:
  DampingTableParams p_;
};

}  // namespace swingsim
