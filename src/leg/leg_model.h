#pragma once
// The Simbody model of the prosthetic leg (Burkett 2004 Fig. 2): Ground -> thigh (pin at the
// hip, its inboard frame Burkett's orientation link placing the hip) -> shank (pin at the
// knee). The foot, welded at the ankle perpendicular to the shank, is part of the shank's
// rigid body (its mass properties added in), so a realization has two bodies to compute.
// Planar, gravity -y, x forward.
//
// With a measured pelvis (a HipPath) a hip carrier sits between the hip's place and the
// thigh: a massless body on a Translation mobilizer whose x, y follow the hip's path (z held
// at 0), so the swing feels the hip's acceleration (docs/moving-hip.md). Without it the hip
// is fixed in space, as Burkett assumed.
//
// With a compliant socket (LegGeometry::socket, docs/socket.md) the thigh body is the residual
// limb; the socket hangs from it on a slide along the thigh (a massless carrier) and a pin at
// the residual limb's end, each with a linear spring and damper, and the knee pin hangs from
// the socket.
//
// Coordinates: hip pin q = hip flexion (counter-clockwise about +z with the subject facing
// +x); knee pin q = knee flexion (its frames are flipped about x so that a positive q
// swings the shank backwards, the clinical sign).
#include <Simbody.h>

#include "knee/joint_stop.h"
#include "knee/knee_law.h"
#include "leg/hip_path.h"
#include "leg/knee_force_element.h"
#include "leg/thigh_motion.h"
#include "model/leg_parameters.h"

namespace swingsim {

/// Ground-frame positions of the chain's landmarks (m), for stick figures and clearance.
struct LegPose {
  SimTK::Vec2 hip, knee, ankle, toe;
};

class LegModel {
 public:
  /// Builds the system. `hipHeight` (m) places the hip above the ground. `trackWork`: also
  /// integrate the work the knee and the hip do (two Z states, for energy bookkeeping);
  /// off, getKneeWork and getHipWork throw std::logic_error.
  /// `prescribedThigh` (the measured thigh drive, SwingDrive::kThighKinematics): if given,
  /// the hip pin follows it as a Simbody prescribed motion (Motion::Custom at position
  /// level) and `hipMoment` and `hipRange` are not used; the hip moment is then the moment
  /// the prescription needs (calcHipMoment). The model keeps its own handle on the fitted
  /// spline.
  /// `hipPath` (only with `prescribedThigh`): the hip joint centre moves along it, displaced
  /// from (0, hipHeight) by hipPath(t) - hipPath(0); else the hip is fixed at (0, hipHeight).
  LegModel(const LegGeometry& geometry, const KneeLaw& knee, const HipMomentProfile& hipMoment,
           const HipRange& hipRange, double hipHeight, bool trackWork = true,
           const ThighMotion* prescribedThigh = nullptr, const HipPath* hipPath = nullptr);
  LegModel(const LegModel&) = delete;
  LegModel& operator=(const LegModel&) = delete;

  const SimTK::MultibodySystem& getSystem() const { return system_; }
  SimTK::MultibodySystem& updSystem() { return system_; }
  const SimTK::SimbodyMatterSubsystem& getMatter() const { return matter_; }

  /// A state at toe-off with the given angles and rates, realized to Velocity.
  SimTK::State makeInitialState(const InitialConditions& initial) const;

  double getHipFlexion(const SimTK::State& s) const { return thigh_.getOneQ(s, 0); }
  double getKneeFlexion(const SimTK::State& s) const { return shank_.getOneQ(s, 0); }
  double getHipFlexionRate(const SimTK::State& s) const { return thigh_.getOneU(s, 0); }
  double getKneeFlexionRate(const SimTK::State& s) const { return shank_.getOneU(s, 0); }
  /// rad/s^2 (Acceleration stage).
  double getHipFlexionAcceleration(const SimTK::State& s) const { return thigh_.getOneUDot(s, 0); }
  double getKneeFlexionAcceleration(const SimTK::State& s) const { return shank_.getOneUDot(s, 0); }
  /// Where the knee's q (and u) sits in the state: 1 with the hip fixed, 4 after the hip
  /// carrier's three translations; 2 more after a compliant socket's slide and pivot.
  int getKneeCoordinateIndex() const { return kneeCoordinate_; }
  /// The hip moves along a measured pelvis path (a hip carrier is in the chain).
  bool hasMovingHip() const { return movingHip_; }
  /// Hip moment, N m, + = flexion: the profile plus the hip range stop; with a prescribed
  /// thigh, the moment the prescribed motion needs (Simbody's tau; Acceleration stage).
  double calcHipMoment(const SimTK::State& s) const;
  /// The thigh follows a prescribed motion (no hip moment drive, no hip work state).
  bool hasPrescribedThigh() const { return hipDrive_ == nullptr; }
  double calcKneeMoment(const SimTK::State& s) const { return knee_->calcKneeMoment(s); }
  /// Knee law states (e.g. Mauch S2) in state s.
  const double* getKneeLawStates(const SimTK::State& s) const { return knee_->getLawStates(s); }
  const KneeLaw& getKneeLaw() const { return knee_->law(); }

  /// Kinetic + gravitational potential energy, J (needs Velocity stage).
  double calcMechanicalEnergy(const SimTK::State& s) const;
  /// The least gravitational potential energy the leg can have with the thigh at
  /// `hipFlexion` (rad), over every knee angle, J (on calcMechanicalEnergy's scale): the shank
  /// and foot turn as one rigid body about the knee, so their potential is
  /// c + a cos(knee) + b sin(knee), found exactly from three knee angles.
  double calcLeastPotentialEnergy(double hipFlexion) const;
  /// Work done on the leg by the knee moment and by the hip moment since toe-off, J.
  double getKneeWork(const SimTK::State& s) const { return knee_->getWork(s); }
  /// Throws std::logic_error with a prescribed thigh (its work is not integrated).
  double getHipWork(const SimTK::State& s) const;
  /// The knee's work split by law part (resisting law, friction, stop, ...): how many parts,
  /// each part's name and its work since toe-off, J. Need trackWork.
  int numKneeWorkParts() const { return knee_->numWorkParts(); }
  std::string getKneeWorkPartName(int i) const { return knee_->getWorkPartName(i); }
  double getKneePartWork(const SimTK::State& s, int i) const { return knee_->getPartWork(s, i); }

  /// The socket gives on the residual limb (LegGeometry::socket).
  bool hasSocket() const { return !socket_.isEmptyHandle(); }
  /// Zero without a compliant socket.
  SocketDeflection getSocketDeflection(const SimTK::State& s) const;

  /// Landmark positions (needs Position stage).
  LegPose calcPose(const SimTK::State& s) const;

 private:
  void addSocket(const LegGeometry& geometry);

  SimTK::MultibodySystem system_;
  SimTK::SimbodyMatterSubsystem matter_;
  SimTK::GeneralForceSubsystem forces_;
  SimTK::MobilizedBody::Translation carrier_;  // only with a moving hip
  SimTK::MobilizedBody::Pin thigh_;
  SimTK::MobilizedBody::Pin shank_;
  SimTK::MobilizedBody::Slider piston_;        // only with a compliant socket
  SimTK::MobilizedBody::Pin socket_;           // only with a compliant socket
  const KneeForceElement* knee_ = nullptr;     // owned by forces_
  const HipDriveElement* hipDrive_ = nullptr;  // owned by forces_; null with a prescribed thigh
  double footLength_;                          // m, ankle to toe (for calcPose)
  double shankLength_;                         // m, knee to ankle (for calcPose)
  int kneeCoordinate_ = 1;
  bool movingHip_ = false;
};

}  // namespace swingsim
