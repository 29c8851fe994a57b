#include "io/knee_model_writer.h"
#include "core/units.h"

#include <sstream>

#include "core/input_error.h"

namespace swingsim {

namespace {


std::string quote(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c == '\n' ? ' ' : c;
  }
  return out + "\"";
}

}  // namespace

std::string formatMauchModelYaml(const MauchCylinderParams& p, const MauchModelText& t) {
  std::ostringstream o;
  std::istringstream header(t.header);
  for (std::string line; std::getline(header, line);) o << "# " << line << "\n";
  const auto n = [](double v) { return formatNumber(v); };
  o << "kind: mauch\n";
  o << "name: " << quote(t.name) << "\n";
  if (!t.description.empty()) o << "description: " << quote(t.description) << "\n";
  o << "phases: " << p.phases << "\n";
  o << "geometry:\n  ab_m: " << n(p.geometry.ab) << "\n  ac_m: " << n(p.geometry.ac) << "\n";
  o << "switches:\n";
  o << "  velocity_width_m_per_s: " << n(p.switches.velocityWidth) << "\n";
  o << "  position_width_m: " << n(p.switches.positionWidth) << "\n";
  o << "  hyperextension_position_m: " << n(p.switches.hyperextensionPosition) << "\n";
  o << "  latch_rate_per_s: " << n(p.switches.latchRate) << "  # 1/k = " << n(1.0 / p.switches.latchRate) << " s\n";
  o << "  initial_latch: " << n(p.initialLatch) << "\n";
  o << "flexion_dial_deg: " << n(t.flexionDial) << "\nextension_dial_deg: " << n(t.extensionDial) << "\n";
  o << "settings:\n  - flexion_dial_deg: " << n(t.flexionDial) << "\n    extension_dial_deg: " << n(t.extensionDial)
    << "\n    coefficients:\n";
  for (std::size_t i = 0; i < p.coefficients.size(); ++i) {
    const auto& c = p.coefficients[i];
    o << "      - {phase: " << i + 1 << ", f_N: " << n(c.f) << ", k_N_per_m: " << n(c.k) << ", c_Ns_per_m: " << n(c.c)
      << "}\n";
  }
  const auto& e = p.effects;
  if (e.any()) {
    o << "effects:\n";
    if (e.hyperextensionPhase)
      o << "  hyperextension_phase: {f_N: " << n(e.hyperextension.f) << ", k_N_per_m: " << n(e.hyperextension.k)
        << ", c_Ns_per_m: " << n(e.hyperextension.c) << "}\n";
    if (e.coulombFriction)
      o << "  coulomb_friction: {force_N: " << n(e.coulombForce) << ", width_m_per_s: " << n(e.coulombWidth) << "}\n";
    if (e.orificeQuadratic) o << "  orifice_quadratic: {coefficient_Ns2_per_m2: " << n(e.orificeCoefficient) << "}\n";
    if (e.inertia) o << "  inertia: {mass_kg: " << n(e.pistonMass) << "}\n";
    if (e.positionDependentDamping)
      o << "  position_dependent_damping: {coefficient_Ns_per_m2: " << n(e.positionDamping) << "}\n";
  }
  o << "hyperextension_stop:\n  engage_flexion_deg: " << n(t.stop.lower * kRadToDeg)
    << "\n  stiffness_Nm_per_rad1p5: " << n(t.stop.stiffness) << "\n  dissipation_s_per_rad: " << n(t.stop.dissipation)
    << "\n";
  return o.str();
}

}  // namespace swingsim
