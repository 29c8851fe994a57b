#include "knee/knee_law.h"

#include <gtest/gtest.h>

#include <memory>
#include <vector>

namespace swingsim {
namespace {

// A spring k (x - z[0]) with one state per law (z' = rate x flexion), so sums can show that
// each part sees its own states at its own offset.
class SpringWithStates final : public KneeLaw {
 public:
  SpringWithStates(double k, int states, double start, bool passive)
      : k_(k), states_(states), start_(start), passive_(passive) {}
  std::string name() const override { return "spring " + std::to_string(static_cast<int>(k_)); }
  int numStates() const override { return states_; }
  void initialStates(double* z) const override {
    for (int i = 0; i < states_; ++i) z[i] = start_ + i;
  }
  double calcMoment(const KneeKinematics& knee, const double* z) const override {
    return -k_ * (knee.flexion - (states_ > 0 ? z[0] : 0.0));
  }
  void calcStateDerivatives(const KneeKinematics& knee, const double* z, double* zdot) const override {
    for (int i = 0; i < states_; ++i) zdot[i] = k_ * knee.flexionRate + z[i];
  }
  bool isPassive() const override { return passive_; }
  double calcStoredEnergy(const KneeKinematics& knee, const double*) const override {
    return 0.5 * k_ * knee.flexion * knee.flexion;
  }
  std::unique_ptr<KneeLaw> clone() const override { return std::make_unique<SpringWithStates>(*this); }

 private:
  double k_;
  int states_;
  double start_;
  bool passive_;
};

KneeLawSum makeSum(bool secondPassive = true) {
  KneeLawSum sum;
  sum.add(std::make_unique<SpringWithStates>(10, 2, 0.1, true));
  sum.add(std::make_unique<SpringWithStates>(20, 0, 0.0, true));
  sum.add(std::make_unique<SpringWithStates>(30, 1, 0.5, secondPassive));
  return sum;
}

TEST(KneeLawSum, ConcatenatesStatesInOrder) {
  const KneeLawSum sum = makeSum();
  ASSERT_EQ(sum.numStates(), 3);
  std::vector<double> z(3);
  sum.initialStates(z.data());
  EXPECT_EQ(z, (std::vector<double>{0.1, 1.1, 0.5}));
  std::vector<double> zdot(3);
  sum.calcStateDerivatives({0.0, 2.0}, z.data(), zdot.data());
  EXPECT_EQ(zdot, (std::vector<double>{10 * 2 + 0.1, 10 * 2 + 1.1, 30 * 2 + 0.5}));
}

TEST(KneeLawSum, MomentIsTheSumOfThePartsAtTheirOwnStates) {
  const KneeLawSum sum = makeSum();
  const std::vector<double> z = {0.1, 7.0, 0.5};
  const KneeKinematics knee{0.3, 0.0};
  // -10 (0.3 - 0.1) - 20 (0.3) - 30 (0.3 - 0.5): the third part reads z[2], not z[1].
  const double parts[] = {-10 * (0.3 - 0.1), -20 * 0.3, -30 * (0.3 - 0.5)};
  for (std::size_t i = 0; i < 3; ++i) EXPECT_DOUBLE_EQ(sum.calcPartMoment(i, knee, z.data()), parts[i]);
  EXPECT_DOUBLE_EQ(sum.calcMoment(knee, z.data()), parts[0] + parts[1] + parts[2]);
  EXPECT_DOUBLE_EQ(sum.calcStoredEnergy(knee, z.data()), 0.5 * (10 + 20 + 30) * 0.3 * 0.3);
  EXPECT_EQ(sum.name(), "spring 10 + spring 20 + spring 30");
}

TEST(KneeLawSum, PassiveOnlyWhenEveryPartIsAndNotEmpty) {
  EXPECT_TRUE(makeSum(true).isPassive());
  EXPECT_FALSE(makeSum(false).isPassive());
  EXPECT_FALSE(KneeLawSum().isPassive());
}

TEST(KneeLawSum, CopiesAreDeepAndKeepTheOffsets) {
  KneeLawSum original = makeSum();
  const KneeLawSum copy = original;
  const std::unique_ptr<KneeLaw> cloned = original.clone();
  original = KneeLawSum();  // the copies own their parts
  const std::vector<double> z = {0.1, 7.0, 0.5};
  const KneeKinematics knee{0.3, 0.0};
  const double expected = -10 * (0.3 - 0.1) - 20 * 0.3 - 30 * (0.3 - 0.5);
  EXPECT_EQ(copy.size(), 3u);
  EXPECT_DOUBLE_EQ(copy.calcMoment(knee, z.data()), expected);
  EXPECT_DOUBLE_EQ(cloned->calcMoment(knee, z.data()), expected);
  EXPECT_EQ(cloned->numStates(), 3);
}

}  // namespace
}  // namespace swingsim
