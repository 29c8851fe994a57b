#include "knee/knee_law.h"

namespace swingsim {

KneeLawSum::KneeLawSum(const KneeLawSum& other) { *this = other; }

KneeLawSum& KneeLawSum::operator=(const KneeLawSum& other) {
  if (this == &other) return *this;
  laws_.clear();
  offsets_.clear();
  for (const auto& law : other.laws_) add(law->clone());
  return *this;
}

void KneeLawSum::add(std::unique_ptr<KneeLaw> law) {
  offsets_.push_back(numStates());
  laws_.push_back(std::move(law));
}

double KneeLawSum::calcPartMoment(std::size_t i, const KneeKinematics& knee, const double* z) const {
  return laws_[i]->calcMoment(knee, z + offsets_[i]);
}

std::string KneeLawSum::name() const {
  std::string s;
  for (const auto& law : laws_) s += (s.empty() ? "" : " + ") + law->name();
  return s;
}

int KneeLawSum::numStates() const {
  int n = 0;
  for (const auto& law : laws_) n += law->numStates();
  return n;
}

void KneeLawSum::initialStates(double* z) const {
  for (std::size_t i = 0; i < laws_.size(); ++i) laws_[i]->initialStates(z + offsets_[i]);
}

double KneeLawSum::calcMoment(const KneeKinematics& knee, const double* z) const {
  double m = 0;
  for (std::size_t i = 0; i < laws_.size(); ++i) m += laws_[i]->calcMoment(knee, z + offsets_[i]);
  return m;
}

void KneeLawSum::calcStateDerivatives(const KneeKinematics& knee, const double* z, double* zdot) const {
  for (std::size_t i = 0; i < laws_.size(); ++i) {
    laws_[i]->calcStateDerivatives(knee, z + offsets_[i], zdot + offsets_[i]);
  }
}

bool KneeLawSum::isPassive() const {
  if (laws_.empty()) return false;
  for (const auto& law : laws_)
    if (!law->isPassive()) return false;
  return true;
}

double KneeLawSum::calcStoredEnergy(const KneeKinematics& knee, const double* z) const {
  double e = 0;
  for (std::size_t i = 0; i < laws_.size(); ++i) e += laws_[i]->calcStoredEnergy(knee, z + offsets_[i]);
  return e;
}

std::unique_ptr<KneeLaw> KneeLawSum::clone() const { return std::make_unique<KneeLawSum>(*this); }

}  // namespace swingsim
