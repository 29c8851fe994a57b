#pragma once
// Test support: integrate a Simbody system and look at it at regular times.
#include <Simbody.h>

#include <functional>

namespace swingsim::testing {

// Integrates `system` from `state` with Simbody's RK-Merson at `accuracy`, calling
// `observe` at every multiple of `interval` up to `duration` (interpolated states,
// realized to Acceleration).
inline void integrateAndObserve(const SimTK::MultibodySystem& system, const SimTK::State& state, double accuracy,
                                double interval, double duration,
                                const std::function<void(const SimTK::State&)>& observe) {
  SimTK::RungeKuttaMersonIntegrator integrator(system);
  integrator.setAccuracy(accuracy);
  integrator.setAllowInterpolation(true);
  SimTK::TimeStepper stepper(system, integrator);
  stepper.initialize(state);
  system.realize(integrator.getState(), SimTK::Stage::Acceleration);
  observe(integrator.getState());
  for (int k = 1; k * interval <= duration + 1e-12; ++k) {
    stepper.stepTo(k * interval);
    system.realize(integrator.getState(), SimTK::Stage::Acceleration);
    observe(integrator.getState());
  }
}

}  // namespace swingsim::testing
