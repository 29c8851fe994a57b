#include "io/participant_loader.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "core/output_files.h"
#include "io/motion_columns_yaml.h"
#include "io/motion_file.h"
#include "io/parts_catalogue_loader.h"
#include "io/swing_events.h"
#include "io/swing_record_csv.h"
#include "io/yaml_archive.h"

namespace swingsim {

// ---- The participant file format, described once ----------------------------------------

struct SegmentsOf {};  // context: the `segments:` map of a participant

std::string checkSegmentLength(double v) {
  if (!(v > 0)) return "must be positive";
  return v <= kMaxSegmentLength ? ""
                                : "expected a segment length of at most " + formatNumber(kMaxSegmentLength) +
                                      " m (is it in millimetres? the key is in metres)";
}

std::string checkSegmentMass(double v) {
  if (!(v > 0)) return "must be positive";
  return v <= kMaxSegmentMass ? ""
                              : "expected a segment mass of at most " + formatNumber(kMaxSegmentMass) +
                                    " kg (heavier than a whole body: is it in grams? the key is in kg)";
}

template <class A>
void serialize(A& a, SegmentParams& s) {
  a.number("length_m", s.length, checkSegmentLength);
  a.number("mass_kg", s.mass, checkSegmentMass);
  a.number("com_from_distal_m", s.comFromDistal, mustBeNonNegative);
  a.number("inertia_kgm2", s.inertia, mustBePositive);
  a.require(s.comFromDistal <= s.length, "com_from_distal_m",
            "the COM must lie on the segment (0.." + formatNumber(s.length) + " m from its distal end)",
            [&] { return formatNumber(s.comFromDistal); });
}

struct LengthOnly {};  // context: a segment whose mass, COM and inertia prosthesis_parts give

template <class A>
void serialize(A& a, SegmentParams& s, LengthOnly) {
  a.number("length_m", s.length, checkSegmentLength);
  if constexpr (A::kReading)
    for (const char* key : {"mass_kg", "com_from_distal_m", "inertia_kgm2"})
      a.require(!a.has(key), key,
                "this segment's mass, COM and inertia come from prosthesis_parts: give length_m only, or drop the "
                "segment's parts from prosthesis_parts",
                [] { return std::string("both"); });
}

template <class A>
void serialize(A& a, Participant& p, SegmentsOf) {
  a.flowMap("thigh", p.thigh);
  if (p.parts && p.parts->makesShank())
    a.flowMap("shank", p.shank, LengthOnly{});
  else
    a.flowMap("shank", p.shank);
  if (p.parts && p.parts->makesFoot())
    a.flowMap("foot", p.foot, LengthOnly{});
  else
    a.flowMap("foot", p.foot);
}

/// prosthesis_parts: {catalogue: FILE (default the shipped one), knee: ID, pylon: ID, ankle: ID,
/// foot: ID}. Reading, the ids are checked against the catalogue, which is kept in `loaded`
/// (if given) for the segments to be made from.
template <class A>
void serialize(A& a, ProsthesisPartsChoice& c, PartsCatalogue* loaded) {
  const std::string shipped = defaultPartsCataloguePath();
  if constexpr (A::kReading) {
    c.cataloguePath = shipped;
    if (a.has("catalogue")) a.path("catalogue", c.cataloguePath);
  } else if (c.cataloguePath != shipped) {
    a.path("catalogue", c.cataloguePath);
  }
  for (PartCategory category : kPartCategories) a.optionalText(partCategoryKey(category), partId(c, category));
  a.require(c.makesShank() || c.makesFoot(), "knee", "expected at least one of knee, pylon, ankle, foot",
            [] { return std::string("none"); });
  if constexpr (A::kReading) {
    PartsCatalogue catalogue = loadPartsCatalogue(c.cataloguePath);
    for (PartCategory category : kPartCategories) {
      const std::string& id = partId(c, category);
      if (id.empty()) continue;
      const std::string problem = checkCataloguePart(catalogue, id, category);
      a.require(problem.empty(), partCategoryKey(category), problem, [&] { return "'" + id + "'"; });
    }
    if (loaded) *loaded = std::move(catalogue);
  }
}

/// socket: {every key optional, MyoSuite's OSL leg by default (model/leg_parameters.h)}.
template <class A>
void serialize(A& a, SocketCompliance& c) {
  const auto within = [](double lo, double hi, const char* what) {
    return [=](double v) {
      return v > lo && v <= hi
                 ? std::string()
                 : "expected " + std::string(what) + " above " + formatNumber(lo) + " and at most " + formatNumber(hi);
    };
  };
  const auto damping = [](double v) { return v >= 0 && v <= 1e6 ? "" : "expected a damping from 0 to 1e6"; };
  a.optionalNumber("piston_stiffness_N_per_m", c.pistonStiffness, within(0, 1e7, "a stiffness in N/m"));
  a.optionalNumber("piston_damping_N_s_per_m", c.pistonDamping, damping);
  a.optionalNumber("rotation_stiffness_Nm_per_rad", c.rotationStiffness, within(0, 1e6, "a stiffness in N m/rad"));
  a.optionalNumber("rotation_damping_Nm_s_per_rad", c.rotationDamping, damping);
  a.optionalNumber("mass_kg", c.mass, within(0, 5, "a socket's mass in kg (is it in grams?)"));
  a.optionalNumber("com_above_pivot_m", c.comAbovePivot, within(-0.5, 0.5, "a distance in m"));
  a.optionalNumber("inertia_kg_m2", c.inertia, within(0, 1, "an inertia about the COM in kg m^2"));
  a.optionalNumber("pivot_above_knee_m", c.pivotAboveKnee, within(0, 0.6, "a distance in m"));
  a.optionalNumber("piston_range_m", c.pistonRange, within(0, 0.2, "a distance in m"));
  a.optionalAngle("rotation_range_deg", c.rotationRange, within(0, 45, "an angle in deg"));
}

template <class A>
void serialize(A& a, InitialConditions& c) {
  a.optionalAngle("hip_flexion_deg", c.hipFlexion, mustBePlausible(kJointAngleRange, "a hip angle"));
  a.optionalAngle("knee_flexion_deg", c.kneeFlexion, mustBePlausible(kInitialKneeRange, "an initial knee angle"));
  a.optionalAngle("hip_flexion_rate_deg_s", c.hipFlexionRate, mustBePlausible(kJointRateRange, "a hip rate"));
  a.optionalAngle("knee_flexion_rate_deg_s", c.kneeFlexionRate, mustBePlausible(kJointRateRange, "a knee rate"));
  // Under the measured thigh drive: the record's knee at toe-off (measured) or the two above.
  if (A::kReading || c.kneeStart != KneeStart::kMeasured)
    a.choice("knee_start", c.kneeStart, {{"measured", KneeStart::kMeasured}, {"initial", KneeStart::kInitial}}, true);
}

template <class A>
void serialize(A& a, HipRange& r) {
  a.optionalAngle("min_flexion_deg", r.minFlexion, mustBePlausible(kJointAngleRange, "a hip angle"));
  a.optionalAngle("max_flexion_deg", r.maxFlexion, mustBePlausible(kJointAngleRange, "a hip angle"));
  a.require(r.maxFlexion > r.minFlexion, "max_flexion_deg", "must exceed min_flexion_deg",
            [&] { return formatNumber(r.maxFlexion * kRadToDeg); });
}

template <class A>
void serialize(A& a, SwingEndRule& e) {
  a.optionalAngle("thigh_target_flexion_deg", e.thighTargetFlexion, mustBePlausible(kJointAngleRange, "a hip angle"));
  a.optionalAngle("zone_of_stability_deg", e.zoneOfStability, mustBePositive);
  // A swing lasts well under a second; a limit of hours would make a stuck run look hung.
  a.optionalNumber("time_limit_s", e.timeLimit,
                   [](double v) { return v > 0 && v <= 10 ? "" : "expected a time limit from 0 to 10 s"; });
  a.optionalNumber("settle_dwell_s", e.settleDwell,
                   [](double v) { return v >= 0 && v <= 2 ? "" : "expected a dwell from 0 to 2 s"; });
}

template <class A>
void serialize(A& a, ToeClearanceRule& t) {
  using G = ToeClearanceRule::Gait;
  a.choice("gait", t.gait, {{"walking", G::kWalking}, {"running", G::kRunning}}, true);
  if constexpr (A::kReading) t.gaitGiven = a.has("gait");
  if constexpr (A::kReading) t.hipRiseGiven = a.has("hip_rise_m");
  if (t.hipRiseGiven)
    a.number("hip_rise_m", t.hipRise, [](double v) {
      return v >= -0.2 && v <= 0.5 ? "" : "expected the hip's rise above standing height, -0.2 to 0.5 m";
    });
}

template <class A>
void serialize(A& a, HipMomentProfile& h) {
  using K = HipMomentProfile::Kind;
  a.choice("profile", h.kind, {{"biphasic_sine", K::kBiphasicSine}, {"table", K::kTable}});
  if (h.kind == K::kTable) {
    a.numbers("time_s", h.times);
    a.numbers("moment_Nm", h.moments);
    for (double m : h.moments)
      a.require(checkPlausible(m, kJointMomentRange, "a hip moment").empty(), "moment_Nm",
                checkPlausible(m, kJointMomentRange, "a hip moment"), [m] { return formatNumber(m); });
    for (double t : h.times)
      a.require(checkPlausible(t, kRecordTimeRange, "a sample time").empty(), "time_s",
                checkPlausible(t, kRecordTimeRange, "a sample time"), [t] { return formatNumber(t); });
    a.require(h.times.size() >= 2, "time_s", "expected at least 2 times",
              [&] { return std::to_string(h.times.size()) + " values"; });
    a.require(h.moments.size() == h.times.size(), "moment_Nm",
              "expected one moment per time (" + std::to_string(h.times.size()) + ")",
              [&] { return std::to_string(h.moments.size()) + " values"; });
    for (std::size_t i = 1; i < h.times.size(); ++i)
      a.require(h.times[i] > h.times[i - 1], "time_s", "times must strictly increase",
                [&] { return formatNumber(h.times[i]) + " after " + formatNumber(h.times[i - 1]); });
  } else {
    const auto amplitude = [](double v) {
      return v >= 0 ? checkPlausible(v, kJointMomentRange, "a hip moment") : "must not be negative";
    };
    a.number("flexion_amplitude_Nm", h.flexionAmplitude, amplitude);
    a.number("flexion_duration_s", h.flexionDuration, mustBePlausible(kPhaseDurationRange, "a phase duration"));
    a.number("extension_amplitude_Nm", h.extensionAmplitude, amplitude);
    a.number("extension_duration_s", h.extensionDuration, mustBePlausible(kPhaseDurationRange, "a phase duration"));
  }
  a.optionalNumber("time_scale", h.timeScale, mustBePlausible(kTimeScaleRange, "a time scale"));
}

/// The map form of thigh_kinematics: {file: F, <motion_columns keys>}.
template <class A>
void serialize(A& a, ThighKinematics& t) {
  a.path("file", t.path);
  a.require(isMotionFile(t.path), "file",
            "an OpenSim .mot/.sto (the map says how to read its columns; a CSV is given by name alone)",
            [&] { return t.path; });
  MotionColumns columns = t.columns.value_or(MotionColumns{});
  serialize(a, columns);
  t.columns = columns;
  // The K-th complete swing found in the file (events from the kinematics), as a study's record takes it.
  std::optional<double> swing;
  if (t.swing) swing = *t.swing;
  optionalSeconds(a, "swing", swing, mustBeSwingNumber);
  if (swing) t.swing = static_cast<int>(*swing);
  a.require(!t.swing || (!columns.toeOffTime && !columns.heelContactTime), "swing",
            "either swing (the K-th swing found in the file) or toe_off_s and heel_contact_s, not both",
            [&] { return std::to_string(t.swing.value_or(0)) + " with times"; });
}

/// `catalogue`, reading: where the catalogue prosthesis_parts names is kept (or nullptr).
template <class A>
void serialize(A& a, Participant& p, PartsCatalogue* catalogue = nullptr) {
  a.text("name", p.name);
  a.optionalText("source", p.source);
  a.number("height_m", p.height,
           [](double v) { return v > 0.5 && v < 2.6 ? "" : "expected a standing height between 0.5 and 2.6 m"; });
  a.number("body_mass_kg", p.bodyMass, [](double v) {
    if (!(v > 0)) return std::string("must be positive");
    return v <= kMaxBodyMass
               ? std::string()
               : "expected a body mass of at most " + formatNumber(kMaxBodyMass) + " kg (is it in grams?)";
  });
  if constexpr (A::kReading)
    if (a.has("prosthesis_parts")) p.parts.emplace();
  if (p.parts) a.map("prosthesis_parts", *p.parts, catalogue);
  a.map("segments", p, SegmentsOf{});
  a.number("knee_friction_Nm", p.kneeFriction, mustBeNonNegative);
  a.path("knee_model", p.kneeModelPath);
  a.choice("com_rule", p.comRule,
           {{"fixed_from_proximal", ComRule::kFixedFromProximal}, {"proportional", ComRule::kProportional}}, true);
  a.choice("foot_com_from", p.footComFrom, {{"toe", FootComFrom::kToe}, {"ankle", FootComFrom::kAnkle}}, true);
  a.optionalNumber("min_shank_length_m", p.minShankLength, mustBePositive);
  optionalSeconds(a, "sound_limb_swing_time_s", p.soundLimbSwingTime, [](double v) {
    return v > 0 && v <= kSwingTimeRange.upper
               ? std::string()
               : "expected a swing time in seconds, above 0 and at most " + formatNumber(kSwingTimeRange.upper);
  });
  a.require(p.minShankLength < p.shank.length, "min_shank_length_m",
            "must be shorter than the shank (" + formatNumber(p.shank.length) + " m)",
            [&] { return formatNumber(p.minShankLength); });
  // The hip joint centre in the pelvis frame [x, y], m (written by import-osim).
  if constexpr (A::kReading)
    if (a.has("hip_offset_in_pelvis_m")) p.hipOffsetInPelvis.emplace();
  if (p.hipOffsetInPelvis) {
    std::vector<double> xy = {(*p.hipOffsetInPelvis)[0], (*p.hipOffsetInPelvis)[1]};
    a.numbers("hip_offset_in_pelvis_m", xy);
    a.require(xy.size() == 2 && std::abs(xy[0]) <= kMaxSegmentLength && std::abs(xy[1]) <= kMaxSegmentLength,
              "hip_offset_in_pelvis_m",
              "expected [x, y] in metres, each within " + formatNumber(kMaxSegmentLength) + " m",
              [&] { return std::to_string(xy.size()) + " values"; });
    p.hipOffsetInPelvis = std::array<double, 2>{xy[0], xy[1]};
  }
  if constexpr (A::kReading)
    if (a.has("socket")) p.socket.emplace();
  if (p.socket) a.map("socket", *p.socket);
  bool present = true;
  a.optionalMap("initial", p.initial, present);
  a.optionalMap("hip_range", p.hipRange, present = true);
  a.optionalMap("toe_clearance", p.toeClearance, present = true);
  a.require(p.initial.hipFlexion >= p.hipRange.minFlexion && p.initial.hipFlexion <= p.hipRange.maxFlexion, "initial",
            "the initial hip flexion must lie inside hip_range",
            [&] { return formatNumber(p.initial.hipFlexion * kRadToDeg) + " deg"; });
  a.optionalMap("swing_end", p.swingEnd, present = true);
  a.require(p.swingEnd.thighTargetFlexion > p.initial.hipFlexion, "swing_end",
            "thigh_target_flexion_deg must be above the initial hip flexion",
            [&] { return formatNumber(p.swingEnd.thighTargetFlexion * kRadToDeg) + " deg"; });
  // The drive: a hip moment profile, or the measured thigh angle.
  if (A::kReading || p.drive != SwingDrive::kHipMoment)
    a.choice("drive", p.drive,
             {{"hip_moment", SwingDrive::kHipMoment}, {"thigh_kinematics", SwingDrive::kThighKinematics}}, true);
  if (p.drive == SwingDrive::kThighKinematics) {
    if constexpr (A::kReading)
      a.require(!a.has("hip_moment"), "hip_moment",
                "no hip moment with drive: thigh_kinematics (the measured thigh drives the swing; the hip moment is an "
                "output)",
                [] { return std::string("a hip_moment map"); });
    // A file name, or a map {file, motion_columns keys} saying how to read a .mot/.sto.
    bool isMap = p.thighKinematics.columns.has_value();
    if constexpr (A::kReading) isMap = a.yaml().isMap("thigh_kinematics");
    if (isMap)
      a.flowMap("thigh_kinematics", p.thighKinematics);
    else
      a.path("thigh_kinematics", p.thighKinematics.path);
  } else {
    a.map("hip_moment", p.hipMoment);
  }
}

// ---- Reading and writing ------------------------------------------------------------------

namespace {

/// The swing record of a .mot/.sto thigh_kinematics: with the map's columns, or a plain
/// name read with OpenSim's right-leg labels (a missing one names the map form).
SwingRecord readThighMotion(const ThighKinematics& t, const ToeClearanceRule& toeClearance, const YamlMap& yaml) {
  const MotionTable table = readMotionTable(t.path);
  if (t.columns) {
    requireNamedColumns(table, *t.columns, yaml.path() + ": thigh_kinematics");
    MotionColumns columns = *t.columns;
    if (t.swing) {
      // The gait toe_clearance states picks the event rules; unstated, it is detected.
      std::optional<Gait> gait;
      if (toeClearance.gaitGiven) gait = toeClearance.gait;
      const FoundSwing swing =
          selectSwing(listSwings(table, columns, std::nullopt, gait), table, columns.knee, *t.swing);
      columns.toeOffTime = swing.toeOff;
      columns.heelContactTime = swing.heelContact;
    }
    return makeSwingRecord(table, columns);
  }
  try {
    return makeSwingRecord(table, openSimRightLegColumns(table));
  } catch (const InputError& e) {
    throw InputError(
        std::string(e.what()) + "\n" + yaml.where("thigh_kinematics") +
        "a plain .mot/.sto name is read with OpenSim's right-leg labels (hip_flexion_r, knee_angle_r, knee_sign -1, "
        "pelvis_tilt/tx/ty when present); for other labels or a cut give the map form {file: F, hip: LABEL, "
        "knee: LABEL, knee_sign: -1, pelvis_tilt: LABEL, toe_off_s: T0, heel_contact_s: T1}");
  }
}

/// The shank and foot the participant's prosthesis_parts make from `catalogue`, the
/// catalogue they name (their ids checked there).
void assembleFromParts(Participant& p, const PartsCatalogue& catalogue, const YamlMap& yaml) {
  const ProsthesisPartsChoice& c = *p.parts;
  auto part = [&](const std::string& id) { return id.empty() ? nullptr : catalogue.find(id); };
  try {
    if (c.makesShank()) {
      p.shank = assembleShank({part(c.knee), part(c.pylon), part(c.ankle)}, p.shank.length);
      // The knee and ankle units keep their heights when the axis is lowered (the pylon is
      // cut): the shank cannot become shorter than the two.
      const double units = (c.knee.empty() ? 0 : part(c.knee)->length) + (c.ankle.empty() ? 0 : part(c.ankle)->length);
      p.minShankLength = std::max(p.minShankLength, units);
    }
    if (c.makesFoot()) p.foot = assembleFoot(*part(c.foot), p.foot.length, p.footComFrom);
  } catch (const std::invalid_argument& e) {
    yaml.fail("prosthesis_parts", e.what(), "the segments' lengths");
  }
}

Participant readParticipant(YamlMap& yaml) {
  Participant p;
  p.path = yaml.path();
  YamlReadArchive a(yaml);
  PartsCatalogue catalogue;
  serialize(a, p, &catalogue);
  yaml.finish();
  if (p.parts) assembleFromParts(p, catalogue, yaml);
  if (p.drive == SwingDrive::kThighKinematics) {
    // The hip (and the pelvis) drive; the knee gives the state at toe-off (leg/toe_off_state.h).
    ThighKinematics& t = p.thighKinematics;
    const SwingRecord record =
        isMotionFile(t.path) ? readThighMotion(t, p.toeClearance, yaml) : readSwingRecord(t.path);
    t.time = record.time;
    t.hipFlexion = record.hipFlexion;
    t.pelvisX = record.pelvisX;
    t.pelvisY = record.pelvisY;
    t.pelvisTilt = record.pelvisTilt;
    t.kneeFlexion = record.kneeFlexion;
  }
  return p;
}

// The comment lines (and blank lines) a file starts with: its provenance, kept on rewrite.
std::string leadingComments(const std::string& text) {
  // A UTF-8 byte-order mark (the reader accepts it) would hide the first comment line.
  const bool bom = text.compare(0, 3, "\xEF\xBB\xBF") == 0;
  std::istringstream in(bom ? text.substr(3) : text);
  std::string line, out;
  while (std::getline(in, line)) {
    const auto first = line.find_first_not_of(" \t\r");
    if (first != std::string::npos && line[first] != '#') break;
    out += line + "\n";
  }
  return out;
}

}  // namespace

Participant loadParticipant(const std::string& path) {
  YamlMap yaml = YamlMap::loadFile(path);
  return readParticipant(yaml);
}

Participant parseParticipant(const std::string& text, const std::string& path) {
  YamlMap yaml = YamlMap::loadString(text, path);
  return readParticipant(yaml);
}

std::string formatParticipantYaml(const Participant& participant, const std::string& baseDir,
                                  const std::string& header) {
  return writeYamlDocument(participant, baseDir, header);
}

void storeParticipants(const std::vector<ParticipantEdit>& edits) {
  namespace fs = std::filesystem;
  struct Staged {
    fs::path target, temp;
  };
  std::vector<Staged> staged;
  auto discard = [&] {
    std::error_code ec;
    for (const auto& s : staged) fs::remove(s.temp, ec);
  };
  try {
    for (const auto& e : edits) {
      std::error_code ec;
      // Write through a symlink: replace what it points to, keep the link.
      const fs::path target = fs::is_symlink(e.path, ec) ? fs::canonical(e.path, ec) : fs::path(e.path);
      if (ec) throw RunError(e.path + ": cannot resolve the symlink: " + ec.message());
      const std::string dir = target.parent_path().empty() ? "." : target.parent_path().string();
      const std::string text = leadingComments(readFile(target.string())) + formatParticipantYaml(e.participant, dir);
      // Loads back to what was meant, or nothing is written.
      const Participant back = parseParticipant(text, target.string());
      if (formatParticipantYaml(back, dir) != formatParticipantYaml(e.participant, dir))
        throw RunError(e.path + ": the rewritten file does not load back to the intended participant; not written");
      const fs::path temp = writeTemporaryBeside(target.string(), text);
      staged.push_back({target, temp});
      fs::permissions(temp, fs::status(target).permissions(), fs::perm_options::replace, ec);
      if (ec) throw RunError(temp.string() + ": cannot set permissions: " + ec.message());
    }
  } catch (...) {
    discard();
    throw;
  }
  for (const auto& s : staged) {
    std::error_code ec;
    fs::rename(s.temp, s.target, ec);
    if (ec) {
      discard();
      throw RunError(s.target.string() + ": cannot replace the file: " + ec.message());
    }
  }
}

}  // namespace swingsim
