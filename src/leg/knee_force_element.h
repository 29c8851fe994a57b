#pragma once
// Simbody adapters: thin Force::Custom implementations over the pure laws of src/knee
// and the hip drive. Each reads its joint's q and u, calls its law, applies a mobility
// moment, and optionally integrates the work it does as a Z state (energy bookkeeping;
// off in swings, where nothing reads it). The knee adapter also integrates the law's own
// states (the Mauch S2 latch).
#include <Simbody.h>

#include <memory>

#include "knee/joint_stop.h"
#include "knee/knee_law.h"
#include "model/hip_moment_profile.h"

namespace swingsim {

/// Knee moment on the knee pin. The knee mobilizer's q is knee flexion (rad), u its rate.
class KneeForceElement : public SimTK::Force::Custom::Implementation {
 public:
  KneeForceElement(const SimTK::GeneralForceSubsystem& forces, const SimTK::SimbodyMatterSubsystem& matter,
                   const SimTK::MobilizedBody& shank, const KneeLaw& law, bool trackWork = true);
  void calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>& bodyForces,
                 SimTK::Vector_<SimTK::Vec3>& particleForces, SimTK::Vector& mobilityForces) const override;
  SimTK::Real calcPotentialEnergy(const SimTK::State&) const override { return 0; }
  void realizeTopology(SimTK::State& s) const override;
  void realizeDynamics(const SimTK::State& s) const override;

  /// Knee moment (N m, + = flexion) in state s (realized to Velocity).
  double calcKneeMoment(const SimTK::State& s) const;
  /// Work done by the knee moment on the leg since toe-off, J (negative: dissipated).
  /// Throws std::logic_error unless built with trackWork.
  double getWork(const SimTK::State& s) const;
  /// Parts whose work is integrated separately: the parts of a KneeLawSum (resisting law,
  /// friction, stop, ...), else 1 (the whole law).
  int numWorkParts() const;
  /// Name of work part i (the law's name()).
  std::string getWorkPartName(int i) const;
  /// Work done by part i since toe-off, J. Throws std::logic_error unless built with trackWork.
  double getPartWork(const SimTK::State& s, int i) const;
  /// The law's own states (e.g. S2), numStates() values.
  const double* getLawStates(const SimTK::State& s) const;
  const KneeLaw& law() const { return *law_; }

 private:
  KneeKinematics kinematics(const SimTK::State& s) const;
  const SimTK::SimbodyMatterSubsystem& matter_;
  SimTK::SubsystemIndex subsystem_;
  SimTK::MobilizedBodyIndex shank_;
  std::unique_ptr<KneeLaw> law_;
  const KneeLawSum* sum_ = nullptr;  // law_ as a sum of parts, or null
  bool trackWork_;
  mutable SimTK::ZIndex firstZ_;  // law states, then the work of each part; set once at topology
};

/// Hip moment on the hip pin: the time profile plus the smooth range-of-motion stop.
class HipDriveElement : public SimTK::Force::Custom::Implementation {
 public:
  HipDriveElement(const SimTK::GeneralForceSubsystem& forces, const SimTK::SimbodyMatterSubsystem& matter,
                  const SimTK::MobilizedBody& thigh, HipMomentProfile profile, JointStopParams range,
                  bool trackWork = true);
  void calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>& bodyForces,
                 SimTK::Vector_<SimTK::Vec3>& particleForces, SimTK::Vector& mobilityForces) const override;
  SimTK::Real calcPotentialEnergy(const SimTK::State&) const override { return 0; }
  void realizeTopology(SimTK::State& s) const override;
  void realizeDynamics(const SimTK::State& s) const override;

  /// Total hip moment (profile + range stop), N m, + = flexion.
  double calcHipMoment(const SimTK::State& s) const;
  /// Work done at the hip since toe-off, J. Throws std::logic_error unless built with trackWork.
  double getWork(const SimTK::State& s) const;

 private:
  const SimTK::SimbodyMatterSubsystem& matter_;
  SimTK::SubsystemIndex subsystem_;
  SimTK::MobilizedBodyIndex thigh_;
  HipMomentProfile profile_;
  JointStop range_;
  bool trackWork_;
  mutable SimTK::ZIndex workZ_;
};

}  // namespace swingsim
