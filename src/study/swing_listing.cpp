#include "study/swing_listing.h"

namespace swingsim {
namespace {

Json disagreementJson(const std::optional<double>& d) { return d ? Json(*d * 1000) : Json(); }

Json swingJson(const FoundSwing& s, std::size_t number) {
  return {{"swing", number},
          {"toe_off_s", s.toeOff},
          {"heel_contact_s", s.heelContact},
          {"duration_s", s.duration()},
          {"toe_off_source", s.toeOffSource},
          {"heel_contact_source", s.heelContactSource},
          {"toe_off_force_minus_kinematics_ms", disagreementJson(s.toeOffDisagreement)},
          {"heel_contact_force_minus_kinematics_ms", disagreementJson(s.heelContactDisagreement)}};
}

}  // namespace

std::string defaultVerticalForce(const std::string& side) {
  return side == "l" ? "1_ground_force_vy" : "ground_force_vy";
}

SwingListing listLegSwings(const SwingListRequest& r) {
  const MotionTable table = readMotionTable(r.kinematics);
  SwingListing out;
  // The leg's OpenSim labels; the thigh's angle in space (hip + pelvis tilt) when the file
  // has the tilt.
  out.columns = openSimLegColumns(table, r.side);
  out.columns.kneeSign = r.kneeSign;
  if (r.grf)
    out.grf = GrfSettings{*r.grf, r.verticalForce.value_or(defaultVerticalForce(r.side)), r.thresholdN,
                          r.fallbackToKinematics};
  std::optional<Gait> gait;
  if (r.gait) gait = *r.gait == "running" ? Gait::kRunning : Gait::kWalking;
  out.list = listSwings(table, out.columns, out.grf, gait);
  if (table.rows() > 1)
    out.framePeriod = (table.columns.front().back() - table.columns.front().front()) / double(table.rows() - 1);
  return out;
}

Json makeSwingListJson(const SwingListRequest& r, const SwingListing& listing) {
  const MotionColumns& columns = listing.columns;
  const std::optional<GrfSettings>& grf = listing.grf;
  const SwingList& list = listing.list;
  Json j;
  j["file"] = r.kinematics;
  j["side"] = r.side;
  j["hip"] = columns.hip;
  j["knee"] = columns.knee;
  j["knee_sign"] = columns.kneeSign;
  j["pelvis_tilt"] = columns.pelvisTilt.empty() ? Json() : Json(columns.pelvisTilt);
  j["grf"] = grf ? Json{{"file", grf->path},
                        {"vertical_force", grf->verticalForce},
                        {"threshold_N", grf->thresholdN},
                        {"fallback_to_kinematics", grf->fallbackToKinematics}}
                 : Json();
  j["gait"] = gaitName(list.gait);
  j["gait_basis"] = list.gaitBasis;
  j["kinematic_accuracy_ms"] = list.kinematicAccuracy * 1000;
  j["kinematic_accuracy_beyond_two_frames"] = list.kinematicAccuracyBeyondTwoFrames;
  j["notes"] = list.notes;
  j["swings"] = Json::array();
  for (std::size_t i = 0; i < list.swings.size(); ++i) j["swings"].push_back(swingJson(list.swings[i], i + 1));
  return j;
}

}  // namespace swingsim
