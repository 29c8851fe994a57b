// The independent swing generator's socket leg (Kane's method in absolute angles) against
// swingsim's reference integrator with the same socket (swing/reference_socket_chain.h,
// Lagrange in relative coordinates): two derivations that share no code must swing alike,
// read through the files a user would have.
#include <gtest/gtest.h>

#include <unistd.h>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "../independent/swing_generator.h"
#include "core/units.h"
#include "io/knee_model_loader.h"
#include "io/participant_loader.h"
#include "swing/knee_setup.h"
#include "swing/reference_swing.h"

namespace swingsim {
namespace {

namespace fs = std::filesystem;

// The drive as the generator's half-sines, sampled every 0.1 ms (linear between samples).
HipMomentProfile tableOf(const independent::HipDrive& drive, double until) {
  HipMomentProfile hip;
  hip.kind = HipMomentProfile::Kind::kTable;
  for (double t = 0; t < until + 0.01; t += 1e-4) {
    hip.times.push_back(t);
    hip.moments.push_back(independent::hipMoment(drive, t));
  }
  return hip;
}

// The lab's thigh (the socket's, deg) and the knee (deg) of the generator and of swingsim's
// reference integrator, each with and without the socket.
struct Swings {
  std::vector<double> thigh, knee;
};

TEST(SwingGenerator, ItsSocketLegSwingsAsSwingsimsReferenceSocketLeg) {
  // The socket's own part of the swing (socket leg minus rigid leg), so that what the two
  // share in both (the knee law's and the drive's small differences, 0.02 deg) cancels.
  independent::SwingTruth truth;
  truth.socket.rotationStiffness = 100.0;
  truth.socket.rotationDamping = 5.0;
  const independent::HipDrive drive = independent::threeDrives()[1];
  const independent::SwingSamples loose = independent::generateSwing(truth, drive, 0.0, 1);
  const independent::SwingSamples rigid = independent::generateSwing(independent::SwingTruth{}, drive, 0.0, 1);

  const fs::path dir = fs::temp_directory_path() / ("swingsim-generator-socket-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  independent::writeSwingModelFiles(truth, dir.string());
  Participant p = loadParticipant((dir / "participant.yaml").string());
  const KneeModel knee = loadKneeModel(p.kneeModelPath);
  fs::remove_all(dir);
  const std::size_t n = std::min(loose.time.size(), rigid.time.size());
  const std::vector<double> times(loose.time.begin(), loose.time.begin() + static_cast<long>(n));
  const HipMomentProfile hip = tableOf(drive, times.back());
  auto swing = [&](const std::optional<SocketCompliance>& socket) {
    Participant q = p;
    q.socket = socket;
    const ReferenceSwing reference(calcLegGeometry(q, 0.0), makeKneeLaw(q, knee), hip, q.hipRange);
    const ReferenceTrajectory tr = reference.integrate(q.initial, times, 1e-10, 1e-10);
    Swings out;
    for (std::size_t i = 0; i < tr.size(); ++i) {
      out.thigh.push_back((socket ? tr.socket[i].calcSocketAngle(tr.hipFlexion[i]) : tr.hipFlexion[i]) * kRadToDeg);
      out.knee.push_back(tr.kneeFlexion[i] * kRadToDeg);
    }
    return out;
  };
  SocketCompliance socket;
  socket.rotationStiffness = truth.socket.rotationStiffness;
  socket.rotationDamping = truth.socket.rotationDamping;
  const Swings withSocket = swing(socket), withoutSocket = swing(std::nullopt);
  double worstThigh = 0, worstKnee = 0, effect = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double generatorThigh = loose.hipDeg[i] - rigid.hipDeg[i];
    const double generatorKnee = loose.cleanKneeDeg[i] - rigid.cleanKneeDeg[i];
    worstThigh = std::max(worstThigh, std::abs(withSocket.thigh[i] - withoutSocket.thigh[i] - generatorThigh));
    worstKnee = std::max(worstKnee, std::abs(withSocket.knee[i] - withoutSocket.knee[i] - generatorKnee));
    effect = std::max(effect, std::abs(generatorKnee));
  }
  std::printf(
      "the socket's part of the swing, generator vs reference over %zu samples: worst thigh %.2e deg, knee "
      "%.2e deg; the socket moves the knee by up to %.2f deg\n",
      n, worstThigh, worstKnee, effect);
  EXPECT_GT(effect, 1.0);  // the socket changes the swing by degrees
  EXPECT_LT(worstThigh, 0.01 * effect);
  EXPECT_LT(worstKnee, 0.01 * effect);
}

}  // namespace
}  // namespace swingsim
