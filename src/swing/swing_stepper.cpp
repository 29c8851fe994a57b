#include "swing/swing_stepper.h"

#include <stdexcept>

namespace swingsim {

using namespace SimTK;

std::unique_ptr<Integrator> makeIntegrator(SwingIntegrator kind, const MultibodySystem& system) {
  switch (kind) {
    case SwingIntegrator::kRungeKuttaFeldberg:
      return std::make_unique<RungeKuttaFeldbergIntegrator>(system);
    case SwingIntegrator::kRungeKutta3:
      return std::make_unique<RungeKutta3Integrator>(system);
    case SwingIntegrator::kVerlet:
      return std::make_unique<VerletIntegrator>(system);
    case SwingIntegrator::kRungeKuttaMerson:
      return std::make_unique<RungeKuttaMersonIntegrator>(system);
    case SwingIntegrator::kCPodes:
      return std::make_unique<CPodesIntegrator>(system, CPodes::BDF, CPodes::Newton);
    case SwingIntegrator::kDormandPrince:
      break;
  }
  throw std::invalid_argument("makeIntegrator: Dormand-Prince is not one of Simbody's integrators");
}

}  // namespace swingsim
