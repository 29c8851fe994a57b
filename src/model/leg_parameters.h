#pragma once
// Plain data describing one participant's prosthetic leg (Burkett 2004 Table 2) and how a
// knee-axis lowering changes it. No Simbody here: the Simbody model and the reference
// integrator both build from LegGeometry.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "core/units.h"
#include "model/hip_moment_profile.h"
#include "model/motion_columns.h"

namespace swingsim {

/// One link as Burkett Table 2 gives it.
struct SegmentParams {
  double length = 0;         ///< m, proximal joint to distal end
  double mass = 0;           ///< kg
  double comFromDistal = 0;  ///< m, from the distal end back towards the proximal joint (Table 2's negative "distance
                             ///< to COM", as a magnitude)
  double inertia = 0;        ///< kg m^2, about the COM (Izz)
};

/// Where each COM goes when the knee axis is lowered by d (Burkett: "the distance from the
/// distal point of the link to the center of mass ... was adjusted").
enum class ComRule {
  /// Thigh COM stays at its distance from the hip, shank COM at its distance from the knee
  /// (the mass moves with the proximal joint: socket stays, knee unit moves down with the
  /// axis; the connecting pipe is < 2 % of mass). Distal-end distances change by +d / -d.
  kFixedFromProximal,
  /// Each COM keeps its fraction of the segment length.
  kProportional,
};

/// Where the foot's COM distance in Table 2 is measured from.
enum class FootComFrom { kToe, kAnkle };

/// Where a swing under the measured thigh drive starts its knee (`initial: knee_start:`).
enum class KneeStart {
  kMeasured,  ///< the record's knee angle and rate at toe-off, when the record has the knee
  kInitial,   ///< the participant's initial knee_flexion_deg and knee_flexion_rate_deg_s
};

/// Initial conditions at toe-off.
struct InitialConditions {
  double hipFlexion = -15 * kDegToRad;  ///< rad
  double kneeFlexion = 10 * kDegToRad;  ///< rad
  double hipFlexionRate = 0;            ///< rad/s (Burkett assumed zero)
  double kneeFlexionRate = 0;           ///< rad/s (Burkett assumed zero)
  /// Under the measured thigh drive the knee starts where the record does; a hip-moment
  /// swing always starts from kneeFlexion and kneeFlexionRate.
  KneeStart kneeStart = KneeStart::kMeasured;
};

/// The swing-end rule: the thigh has reached its defined flexion position AND the knee,
/// after its peak flexion, is back inside the zone of stability, in whichever order.
struct SwingEndRule {
  double thighTargetFlexion = 20 * kDegToRad;  ///< rad
  double zoneOfStability = 6 * kDegToRad;      ///< rad (Burkett Fig. 3: < 6 deg)
  double timeLimit = 1.5;                      ///< s: a swing not ended by then is an error
  /// s the knee must stay inside the zone for the swing to have ended (the settle rule):
  /// the swing ends at the last entry into the zone that is followed by this long inside it,
  /// so a bounce out of the zone lengthens the swing. An assumption (no source defines it):
  /// longer than a rebound off the stop and back out of the zone takes (about 0.1 s at
  /// 2-3 rad/s), plausible range 0.10-0.20 s (docs/uncertainty.md).
  double settleDwell = 0.15;
};

/// The gait a swing belongs to: where the toe clearance is measured against, and which
/// kinematic rules find a recording's swing events (io/swing_events.h).
enum class Gait { kWalking, kRunning };

/// What the toe clearance is measured against. The foot's height is computed with the hip at
/// standing hip height (0.530 x height) plus `hipRise`; whether a negative clearance means
/// the foot strikes the ground depends on the gait: in walking the swing happens over the
/// stance leg with the hip near standing height, in running the body is in flight for much
/// of the swing and the hip is higher by an amount nobody here measured.
struct ToeClearanceRule {
  using Gait = swingsim::Gait;
  Gait gait = Gait::kWalking;
  bool gaitGiven = false;  ///< `gait:` was written (it then also picks a thigh_kinematics swing's event rules)
  /// m, the hip's height above standing hip height during the swing (a user's measured
  /// pelvis, e.g. from motion capture); applied as a constant offset.
  double hipRise = 0;
  bool hipRiseGiven = false;  ///< `hip_rise_m:` was written
  /// The strike alarm holds: walking, or running with a stated hip rise.
  bool alarmHolds() const { return gait == Gait::kWalking || hipRiseGiven; }
};

/// Physiological hip range of motion (smooth stop outside it).
struct HipRange {
  double minFlexion = -30 * kDegToRad;  ///< rad
  double maxFlexion = 90 * kDegToRad;   ///< rad
};

/// A point mass added to the shank (Bach 1994), at a distance below the knee axis.
struct AddedMass {
  double mass = 0;               ///< kg
  double distanceBelowKnee = 0;  ///< m, along the shank
};

/// What drives the swing: a hip moment, or the measured thigh angle prescribed on the hip.
enum class SwingDrive {
  /// A hip moment (HipMomentProfile) drives the thigh; thigh, shank and foot swing freely.
  kHipMoment,
  /// The measured thigh angle is prescribed on the hip (ThighKinematics); shank and foot
  /// swing freely under gravity, the knee law and the stop, and the hip moment the
  /// prescription needs is an output.
  kThighKinematics,
};

/// A measured thigh (hip flexion) angle over a swing: the `thigh_kinematics:` file of a
/// participant (a swing kinematics CSV or a motion file), or a measured swing record.
struct ThighKinematics {
  std::string path;  ///< file it was read from ("" = given in code)
  /// s from toe-off (first sample at 0); the thigh's angle in space, rad (hip flexion plus
  /// pelvis tilt when the recording has the pelvis).
  std::vector<double> time, hipFlexion;
  /// The measured pelvis at the same times: translation in the ground frame, m (x forward,
  /// y up), and tilt about +z, rad. Empty = the hip is fixed in space (Burkett's assumption).
  std::vector<double> pelvisX, pelvisY, pelvisTilt;
  /// The measured knee flexion at the same times, rad; empty = not measured. It never drives
  /// the leg: it gives the knee's state at toe-off (leg/toe_off_state.h).
  std::vector<double> kneeFlexion;
  /// The K-th complete swing (1-based) found in the .mot/.sto (`swing: K` in the map form),
  /// instead of toe_off_s and heel_contact_s.
  std::optional<int> swing;
  /// How a .mot/.sto was read, when the file gave it as a map ({file, motion_columns keys,
  /// toe_off_s, heel_contact_s}); nullopt: a plain file name (OpenSim right-leg labels).
  std::optional<MotionColumns> columns;
};

/// The parts a participant names (`prosthesis_parts:`, docs/parts.md); an empty id names none.
struct ProsthesisPartsChoice {
  std::string cataloguePath;  ///< resolved; the shipped catalogue unless the file names another
  std::string knee, pylon, ankle, foot;
  bool makesShank() const { return !knee.empty() || !pylon.empty() || !ankle.empty(); }
  bool makesFoot() const { return !foot.empty(); }
};

/// Socket compliance (docs/socket.md): the socket, and the prosthesis hanging from it, ride on
/// the residual limb through a pistoning slide along the thigh and a sagittal rotation about a
/// pivot at the residual limb's end, each a linear spring and damper. Defaults: MyoSuite's
/// transfemoral OSL leg (MyoHub/myo_sim@2cef885 `osl/assets/myolegs_osl_chain.xml`, body
/// `prosthetic_socket`: joints `socket_piston` and `socket_rotation_1`); its socket's mass is
/// taken out of the thigh segment, which Burkett's Table 2 gives as residual limb plus socket.
struct SocketCompliance {
  double pistonStiffness = 20000;   ///< N/m (socket_piston stiffness)
  double pistonDamping = 10000;     ///< N s/m (socket_piston damping)
  double rotationStiffness = 350;   ///< N m/rad (socket_rotation_1 stiffness)
  double rotationDamping = 175;     ///< N m s/rad (socket_rotation_1 damping)
  double mass = 0.849991;           ///< kg (prosthetic_socket inertial mass)
  double comAbovePivot = 0.101169;  ///< m, along the thigh (prosthetic_socket inertial pos y)
  double inertia = 0.0039776;       ///< kg m^2 about the COM, sagittal (diaginertia rotated by its quat)
  double pivotAboveKnee = 0.11270;  ///< m, unlowered (the femoral pylon's 0.02829 + the adapter's 0.08441)
  double pistonRange = 0.035;       ///< m: MyoSuite's joint range; a swing past it is reported
  double rotationRange = 0.122173;  ///< rad (7 deg), as pistonRange
};

/// A compliant socket's deflection on the residual limb: m (+ = pulled off the limb) and rad
/// (+ = the socket flexed on the limb, the hip's sense).
struct SocketDeflection {
  double piston = 0, rotation = 0;
  /// The socket's angle from hanging straight down (rad; or its rate, of rates) on a residual
  /// limb at `limbFlexion`: where a lab's thigh markers are, on the socket.
  double calcSocketAngle(double limbFlexion) const { return limbFlexion + rotation; }
};

struct Participant {
  std::string path;  ///< file it was loaded from
  std::string name;
  std::string source;   ///< where the numbers come from (free text)
  double height = 0;    ///< m, standing height
  double bodyMass = 0;  ///< kg
  SegmentParams thigh, shank, foot;
  double kneeFriction = 0;    ///< Tc, N m (Burkett Table 2)
  std::string kneeModelPath;  ///< resolved path of the knee model YAML
  ComRule comRule = ComRule::kFixedFromProximal;
  FootComFrom footComFrom = FootComFrom::kToe;
  InitialConditions initial;
  SwingEndRule swingEnd;
  ToeClearanceRule toeClearance;
  HipRange hipRange;
  SwingDrive drive = SwingDrive::kHipMoment;
  HipMomentProfile hipMoment;       ///< the drive if drive == kHipMoment
  ThighKinematics thighKinematics;  ///< the drive if drive == kThighKinematics
  double minShankLength = 0.10;     ///< m: the knee unit and pylon clamp need at least this
  /// The hip joint centre in the pelvis frame, m (x forward, y up): where the hip sits when
  /// a measured pelvis moves it (`hip_offset_in_pelvis_m`; written by import-osim).
  std::optional<std::array<double, 2>> hipOffsetInPelvis;
  /// The sound (anatomical) limb's measured swing time, s (`sound_limb_swing_time_s`): the
  /// symmetry target of the sweep and of tuning. nullopt: not measured.
  std::optional<double> soundLimbSwingTime;
  /// The prosthesis parts the shank and foot are made of (model/prosthesis_parts.h); the
  /// segments they make are in shank and foot. nullopt: the segments' masses as written.
  std::optional<ProsthesisPartsChoice> parts;
  /// `socket:`: the socket's give (off = the socket is rigid on the residual limb, Burkett's leg).
  std::optional<SocketCompliance> socket;
};

/// The leg as the dynamics sees it, after lowering: distances from the proximal joint.
struct LegGeometry {
  double thighLength, thighMass, thighCom, thighInertia;  ///< thighCom: m below the hip along the thigh
  double shankLength, shankMass, shankCom, shankInertia;  ///< shankCom: m below the knee
  double footLength, footMass, footComForward,
      footInertia;  ///< footComForward: m ahead of the ankle, foot perpendicular to the shank
  AddedMass added;
  /// The socket's give; nullopt = rigid. Its pivot stays at `socketPivotBelowHip` under a
  /// lowering (the residual limb does not change; the knee moves down the pylon).
  std::optional<SocketCompliance> socket;
  double socketPivotBelowHip = 0;  ///< m, with `socket`
};

/// Applies a knee-axis lowering `lowering` (m, >= 0): thigh + d, shank - d, inertias about
/// the COMs unchanged, COMs per `comRule`. Throws InputError if the shank would be shorter
/// than `minShankLength` or a COM would leave its segment.
LegGeometry calcLegGeometry(const Participant& participant, double lowering, const AddedMass& added = {});

/// A planar segment's mass properties: kg, m below the hip along the thigh, kg m^2 about the COM.
struct SegmentMassProperties {
  double mass, com, inertia;
};

/// The residual limb alone with a compliant socket: the thigh segment less the socket, at
/// zero deflection (so the two together are the thigh segment exactly).
SegmentMassProperties calcResidualLimb(const LegGeometry& geometry);

/// Ground-frame landmark positions (m) from the joint angles, by planar kinematics: hip at
/// (0, hipHeight), x forward, y up; the foot points along +x of the shank.
struct PlanarPose {
  double hip[2], knee[2], ankle[2], toe[2];
};
/// With a compliant socket (g.socket), its deflection `socket` places the knee; without one it
/// is ignored.
PlanarPose calcPlanarPoseXY(const LegGeometry& g, double hipHeight, double hipFlexion, double kneeFlexion,
                            const SocketDeflection& socket = {});

/// The largest lowering `calcLegGeometry` accepts for this participant, m.
double calcMaxLowering(const Participant& participant);

}  // namespace swingsim
