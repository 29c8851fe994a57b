#include "leg/knee_force_element.h"

#include <stdexcept>
#include <vector>

namespace swingsim {

using namespace SimTK;

KneeForceElement::KneeForceElement(const GeneralForceSubsystem& forces, const SimbodyMatterSubsystem& matter,
                                   const MobilizedBody& shank, const KneeLaw& law, bool trackWork)
    : matter_(matter),
      subsystem_(forces.getMySubsystemIndex()),
      shank_(shank.getMobilizedBodyIndex()),
      law_(law.clone()),
      sum_(dynamic_cast<const KneeLawSum*>(law_.get())),
      trackWork_(trackWork) {}

int KneeForceElement::numWorkParts() const { return sum_ ? static_cast<int>(sum_->size()) : 1; }

std::string KneeForceElement::getWorkPartName(int i) const {
  return sum_ ? sum_->part(static_cast<std::size_t>(i)).name() : law_->name();
}

KneeKinematics KneeForceElement::kinematics(const State& s) const {
  const MobilizedBody& shank = matter_.getMobilizedBody(shank_);
  const MobilizedBody& thigh = shank.getParentMobilizedBody();
  return {shank.getOneQ(s, 0), shank.getOneU(s, 0), thigh.getOneQ(s, 0), thigh.getOneU(s, 0), s.getTime()};
}

void KneeForceElement::realizeTopology(State& s) const {
  const int nz = law_->numStates() + (trackWork_ ? numWorkParts() : 0);
  if (nz == 0) return;
  Vector z(nz, 0.0);
  if (law_->numStates() > 0) law_->initialStates(&z[0]);
  firstZ_ = s.allocateZ(subsystem_, z);
}

const double* KneeForceElement::getLawStates(const State& s) const {
  if (law_->numStates() == 0) return nullptr;  // laws without states do not read z
  return &s.getZ(subsystem_)[firstZ_];
}

double KneeForceElement::calcKneeMoment(const State& s) const {
  return law_->calcMoment(kinematics(s), getLawStates(s));
}

double KneeForceElement::getPartWork(const State& s, int i) const {
  if (!trackWork_) throw std::logic_error("KneeForceElement: built without work tracking");
  return s.getZ(subsystem_)[firstZ_ + law_->numStates() + i];
}

double KneeForceElement::getWork(const State& s) const {
  double work = 0;
  for (int i = 0; i < numWorkParts(); ++i) work += getPartWork(s, i);
  return work;
}

void KneeForceElement::calcForce(const State& s, Vector_<SpatialVec>&, Vector_<Vec3>&, Vector& mobilityForces) const {
  matter_.getMobilizedBody(shank_).applyOneMobilityForce(s, 0, calcKneeMoment(s), mobilityForces);
}

void KneeForceElement::realizeDynamics(const State& s) const {
  if (law_->numStates() == 0 && !trackWork_) return;
  const KneeKinematics knee = kinematics(s);
  const double* z = getLawStates(s);
  Vector& zdot = s.updZDot(subsystem_);
  const int n = law_->numStates();
  if (n > 0) law_->calcStateDerivatives(knee, z, &zdot[firstZ_]);
  if (!trackWork_) return;
  // Power of each part, W.
  if (sum_ == nullptr) {
    zdot[firstZ_ + n] = law_->calcMoment(knee, z) * knee.flexionRate;
    return;
  }
  for (std::size_t i = 0; i < sum_->size(); ++i)
    zdot[firstZ_ + n + static_cast<int>(i)] = sum_->calcPartMoment(i, knee, z) * knee.flexionRate;
}

HipDriveElement::HipDriveElement(const GeneralForceSubsystem& forces, const SimbodyMatterSubsystem& matter,
                                 const MobilizedBody& thigh, HipMomentProfile profile, JointStopParams range,
                                 bool trackWork)
    : matter_(matter),
      subsystem_(forces.getMySubsystemIndex()),
      thigh_(thigh.getMobilizedBodyIndex()),
      profile_(std::move(profile)),
      range_(range),
      trackWork_(trackWork) {}

void HipDriveElement::realizeTopology(State& s) const {
  if (trackWork_) workZ_ = s.allocateZ(subsystem_, Vector(1, 0.0));
}

double HipDriveElement::calcHipMoment(const State& s) const {
  const MobilizedBody& thigh = matter_.getMobilizedBody(thigh_);
  return profile_.calcMoment(s.getTime()) + range_.calcJointMoment(thigh.getOneQ(s, 0), thigh.getOneU(s, 0));
}

double HipDriveElement::getWork(const State& s) const {
  if (!trackWork_) throw std::logic_error("HipDriveElement: built without work tracking");
  return s.getZ(subsystem_)[workZ_];
}

void HipDriveElement::calcForce(const State& s, Vector_<SpatialVec>&, Vector_<Vec3>&, Vector& mobilityForces) const {
  matter_.getMobilizedBody(thigh_).applyOneMobilityForce(s, 0, calcHipMoment(s), mobilityForces);
}

void HipDriveElement::realizeDynamics(const State& s) const {
  if (!trackWork_) return;
  s.updZDot(subsystem_)[workZ_] = calcHipMoment(s) * matter_.getMobilizedBody(thigh_).getOneU(s, 0);
}

}  // namespace swingsim
