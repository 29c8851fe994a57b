#include "leg/leg_model.h"

#include <stdexcept>

namespace swingsim {

using namespace SimTK;

namespace {

// Planar segment: mass m with its COM at `com` in the body frame and moment of inertia
// izz about the COM (Burkett Table 2's Izz). Ixx = Iyy = Izz keeps the inertia physical;
// only Izz acts in this planar chain.
MassProperties segmentMassProperties(double m, const Vec3& com, double izz) {
  return MassProperties(m, com, Inertia(izz).shiftFromMassCenter(com, m));
}

// The shank's rigid body in its frame (origin at the knee, -y towards the ankle): the shank
// segment, an optional added point mass (Bach 1994) below the knee, and the foot welded at
// the ankle at 90 deg to the shank, pointing forward (+x), its COM footComForward ahead of
// the ankle. Masses add, COMs average by mass, inertias about the knee add.
MassProperties calcShankFootMassProperties(const LegGeometry& g) {
  const Vec3 ankle(0, -g.shankLength, 0);
  struct Part {
    double mass;
    Vec3 com;
    Inertia aboutKnee;
  };
  const Vec3 shankCom(0, -g.shankCom, 0), addedAt(0, -g.added.distanceBelowKnee, 0),
      footCom = ankle + Vec3(g.footComForward, 0, 0);
  const Part parts[] = {
      {g.shankMass, shankCom, Inertia(g.shankInertia).shiftFromMassCenter(shankCom, g.shankMass)},
      {g.added.mass, addedAt, Inertia::pointMassAt(addedAt, g.added.mass)},
      {g.footMass, footCom, Inertia(g.footInertia).shiftFromMassCenter(footCom, g.footMass)},
  };
  double mass = 0;
  Vec3 moment(0);
  Inertia aboutKnee(0);
  for (const Part& part : parts) {
    if (!(part.mass > 0)) continue;
    mass += part.mass;
    moment += part.mass * part.com;
    aboutKnee += part.aboutKnee;
  }
  return MassProperties(mass, moment / mass, aboutKnee);
}

// The measured thigh angle on the hip pin (q = hip flexion): position, rate and
// acceleration from the same quintic spline, so each is the exact derivative of the last.
class PrescribedThighImpl final : public Motion::Custom::Implementation {
 public:
  explicit PrescribedThighImpl(const ThighMotion& motion) : motion_(motion) {}
  Implementation* clone() const override { return new PrescribedThighImpl(motion_); }
  Motion::Level getLevel(const State&) const override { return Motion::Position; }
  void calcPrescribedPosition(const State& s, int nq, Real* q) const override {
    if (nq == 1) q[0] = motion_.calcAngle(s.getTime());
  }
  void calcPrescribedPositionDot(const State& s, int nq, Real* qdot) const override {
    if (nq == 1) qdot[0] = motion_.calcRate(s.getTime());
  }
  void calcPrescribedPositionDotDot(const State& s, int nq, Real* qdotdot) const override {
    if (nq == 1) qdotdot[0] = motion_.calcAcceleration(s.getTime());
  }

 private:
  ThighMotion motion_;  // shares the fitted spline
};

// The hip carrier's translation (x, y, z) in the orientation frame: the hip path's
// displacement from its start, z held at 0.
class PrescribedHipImpl final : public Motion::Custom::Implementation {
 public:
  explicit PrescribedHipImpl(const HipPath& path) : path_(path), start_(path.calcPosition(0)) {}
  Implementation* clone() const override { return new PrescribedHipImpl(path_); }
  Motion::Level getLevel(const State&) const override { return Motion::Position; }
  void calcPrescribedPosition(const State& s, int nq, Real* q) const override {
    const std::array<double, 2> p = path_.calcPosition(s.getTime());
    set(nq, q, p[0] - start_[0], p[1] - start_[1]);
  }
  void calcPrescribedPositionDot(const State& s, int nq, Real* qdot) const override {
    const std::array<double, 2> v = path_.calcVelocity(s.getTime());
    set(nq, qdot, v[0], v[1]);
  }
  void calcPrescribedPositionDotDot(const State& s, int nq, Real* qdotdot) const override {
    const std::array<double, 2> a = path_.calcAcceleration(s.getTime());
    set(nq, qdotdot, a[0], a[1]);
  }

 private:
  static void set(int nq, Real* out, double x, double y) {
    if (nq != 3) return;
    out[0] = x;
    out[1] = y;
    out[2] = 0;
  }
  HipPath path_;  // shares the fitted splines
  std::array<double, 2> start_;
};

}  // namespace

LegModel::LegModel(const LegGeometry& g, const KneeLaw& knee, const HipMomentProfile& hipMoment,
                   const HipRange& hipRange, double hipHeight, bool trackWork, const ThighMotion* prescribedThigh,
                   const HipPath* hipPath)
    : matter_(system_), forces_(system_), footLength_(g.footLength), shankLength_(g.shankLength) {
  Force::UniformGravity(forces_, matter_, Vec3(0, -kGravity, 0));

  // Burkett's orientation link (a massless weld placing the hip in space) is the hip pin's
  // inboard frame on Ground, and the foot (welded to the shank at the ankle) is part of the
  // shank's rigid body: the same dynamics with two bodies fewer to realize (docs/speed.md).
  const Transform hipInGround(Vec3(0, hipHeight, 0));

  if (hipPath != nullptr && prescribedThigh == nullptr)
    throw std::invalid_argument("LegModel: a moving hip needs the measured thigh drive");
  // The hip carrier: massless, so it adds nothing to the dynamics but the hip's motion (its
  // mobilities are all prescribed, so its zero mass never enters the mass matrix that is
  // solved).
  movingHip_ = hipPath != nullptr;
  if (movingHip_) {
    carrier_ = MobilizedBody::Translation(matter_.Ground(), hipInGround, Body::Massless(), Transform());
    Motion::Custom(carrier_, new PrescribedHipImpl(*hipPath));
  }
  // With a compliant socket the thigh body is the residual limb alone (docs/socket.md).
  const SegmentMassProperties limb = calcResidualLimb(g);
  const Body::Rigid thighBody(segmentMassProperties(limb.mass, Vec3(0, -limb.com, 0), limb.inertia));
  thigh_ = movingHip_ ? MobilizedBody::Pin(carrier_, Transform(), thighBody, Transform())
                      : MobilizedBody::Pin(matter_.Ground(), hipInGround, thighBody, Transform());

  // What the knee pin hangs from: the thigh, or the socket on its slide and pivot.
  MobilizedBody kneeParent = thigh_;
  Vec3 kneeInParent(0, -g.thighLength, 0);
  if (g.socket) {
    addSocket(g);
    kneeParent = socket_;
    kneeInParent = Vec3(0, -(g.thighLength - g.socketPivotBelowHip), 0);
  }
  kneeCoordinate_ = (movingHip_ ? 4 : 1) + (g.socket ? 2 : 0);

  const Rotation flip(Pi, XAxis);  // makes the knee pin's +q a flexion (see header)
  shank_ = MobilizedBody::Pin(kneeParent, Transform(flip, kneeInParent), Body::Rigid(calcShankFootMassProperties(g)),
                              Transform(flip, Vec3(0)));

  JointStopParams range;
  range.lower = hipRange.minFlexion;
  range.upper = hipRange.maxFlexion;
  auto* kneeImpl = new KneeForceElement(forces_, matter_, shank_, knee, trackWork);
  knee_ = kneeImpl;
  Force::Custom(forces_, kneeImpl);
  if (prescribedThigh != nullptr) {
    Motion::Custom(thigh_, new PrescribedThighImpl(*prescribedThigh));
  } else {
    auto* hipImpl = new HipDriveElement(forces_, matter_, thigh_, hipMoment, range, trackWork);
    hipDrive_ = hipImpl;
    Force::Custom(forces_, hipImpl);
  }

  system_.realizeTopology();
}

void LegModel::addSocket(const LegGeometry& g) {
  const SocketCompliance& c = *g.socket;
  // The slide: Simbody's Slider moves along its frames' common x, turned here to point down
  // the thigh (+q pulls the socket off the limb). A massless carrier holds the slide's
  // displacement; the socket pin turns about the pivot (+q flexes the socket and all below
  // it on the limb, the hip's sense).
  const Rotation alongThigh(-Pi / 2, ZAxis);
  piston_ = MobilizedBody::Slider(thigh_, Transform(alongThigh, Vec3(0, -g.socketPivotBelowHip, 0)), Body::Massless(),
                                  Transform(alongThigh));
  socket_ = MobilizedBody::Pin(piston_, Transform(),
                               Body::Rigid(segmentMassProperties(c.mass, Vec3(0, c.comAbovePivot, 0), c.inertia)),
                               Transform());
  Force::MobilityLinearSpring(forces_, piston_, MobilizerUIndex(0), c.pistonStiffness, 0);
  Force::MobilityLinearDamper(forces_, piston_, MobilizerUIndex(0), c.pistonDamping);
  Force::MobilityLinearSpring(forces_, socket_, MobilizerUIndex(0), c.rotationStiffness, 0);
  Force::MobilityLinearDamper(forces_, socket_, MobilizerUIndex(0), c.rotationDamping);
}

State LegModel::makeInitialState(const InitialConditions& initial) const {
  State s = system_.getDefaultState();
  thigh_.setOneQ(s, 0, initial.hipFlexion);
  shank_.setOneQ(s, 0, initial.kneeFlexion);
  thigh_.setOneU(s, 0, initial.hipFlexionRate);
  shank_.setOneU(s, 0, initial.kneeFlexionRate);
  if (hasPrescribedThigh()) {  // the thigh's (and hip's) q and u from their prescribed motion at t = 0
    system_.realize(s, Stage::Time);
    system_.prescribeQ(s);
    system_.realize(s, Stage::Position);
    system_.prescribeU(s);
  }
  system_.realize(s, Stage::Velocity);
  return s;
}

double LegModel::calcHipMoment(const State& s) const {
  if (hipDrive_ != nullptr) return hipDrive_->calcHipMoment(s);
  // Simbody's tau is the generalized force the Motion exerts with the sign of a multiplier
  // (it enters the equations as M udot + tau = applied forces): the hip moment the
  // prescription needs is its negative (checked against the reference integrator's
  // inverse dynamics and by the round trip, tests/swing/thigh_drive_test.cpp).
  return -thigh_.getOneTau(s, MobilizerUIndex(0));
}

double LegModel::getHipWork(const State& s) const {
  if (hipDrive_ == nullptr)
    throw std::logic_error("LegModel::getHipWork: the thigh is prescribed; its work is not integrated");
  return hipDrive_->getWork(s);
}

double LegModel::calcMechanicalEnergy(const State& s) const {
  return system_.calcKineticEnergy(s) + system_.calcPotentialEnergy(s);
}

double LegModel::calcLeastPotentialEnergy(double hipFlexion) const {
  State s = system_.getDefaultState();
  thigh_.setOneQ(s, 0, hipFlexion);
  const auto potentialAt = [&](double knee) {
    shank_.setOneQ(s, 0, knee);
    system_.realize(s, Stage::Position);
    return system_.calcPotentialEnergy(s);
  };
  const double v0 = potentialAt(0), v90 = potentialAt(Pi / 2), v180 = potentialAt(Pi);
  const double c = 0.5 * (v0 + v180), a = 0.5 * (v0 - v180), b = v90 - c;
  return c - std::sqrt(a * a + b * b);
}

SocketDeflection LegModel::getSocketDeflection(const State& s) const {
  if (!hasSocket()) return {};
  return {piston_.getOneQ(s, 0), socket_.getOneQ(s, 0)};
}

LegPose LegModel::calcPose(const State& s) const {
  auto at = [&](const MobilizedBody& b, const Vec3& p) {
    Vec3 g = b.findStationLocationInGround(s, p);
    return Vec2(g[0], g[1]);
  };
  LegPose pose;
  pose.hip = at(thigh_, Vec3(0));
  pose.knee = at(shank_, Vec3(0));
  pose.ankle = at(shank_, Vec3(0, -shankLength_, 0));
  pose.toe = at(shank_, Vec3(footLength_, -shankLength_, 0));
  return pose;
}

}  // namespace swingsim
