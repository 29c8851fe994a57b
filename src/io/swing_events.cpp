#include "io/swing_events.h"

#include <algorithm>
#include <cmath>

#include "core/input_error.h"
#include "core/units.h"

namespace swingsim {

namespace {

enum class Kind { ToeOff, HeelContact };

struct Event {
  double time;
  Kind kind;
  const char* source;
};

/// The time of a crossing of `level` between rows k-1 and k, by linear interpolation.
double crossingTime(const std::vector<double>& t, const std::vector<double>& f, std::size_t k, double level) {
  return t[k - 1] + (t[k] - t[k - 1]) * (level - f[k - 1]) / (f[k] - f[k - 1]);
}

/// Toe-off where the vertical force falls below the threshold, heel contact where it rises
/// above it. A phase shorter than kMinGaitPhaseS is the force hovering at the threshold:
/// its two crossings go, so each event is the crossing after which the force stays on the
/// new side for at least that long.
std::vector<Event> calcGrfEvents(const MotionTable& grf, const GrfSettings& settings) {
  const std::vector<double>& t = grf.columns.front();
  const std::vector<double>& f = grf.column(settings.verticalForce);
  std::vector<Event> events;
  for (std::size_t k = 1; k < t.size(); ++k) {
    const bool wasLoaded = f[k - 1] >= settings.thresholdN, isLoaded = f[k] >= settings.thresholdN;
    if (wasLoaded == isLoaded) continue;
    events.push_back({crossingTime(t, f, k, settings.thresholdN), isLoaded ? Kind::HeelContact : Kind::ToeOff, "grf"});
  }
  // Removing a short phase's two crossings keeps the events alternating.
  for (std::size_t i = 0; i + 1 < events.size();) {
    if (events[i + 1].time - events[i].time < kMinGaitPhaseS)
      events.erase(events.begin() + static_cast<std::ptrdiff_t>(i), events.begin() + static_cast<std::ptrdiff_t>(i + 2));
    else
      ++i;
  }
  return events;
}

/// The time of the extremum of x at row k (an interior row), from the parabola through
/// rows k-1, k, k+1: sub-frame timing on even steps.
double vertexTime(const std::vector<double>& t, const std::vector<double>& x, std::size_t k) {
  const double curvature = x[k - 1] - 2 * x[k] + x[k + 1];
  const double step = 0.5 * (t[k + 1] - t[k - 1]);
  if (curvature == 0) return t[k];
  const double shift = std::clamp(0.5 * (x[k - 1] - x[k + 1]) / curvature, -1.0, 1.0);
  return t[k] + shift * step;
}

/// The leg's angles from the kinematics, rad: the thigh's (in space when the pelvis tilt is
/// named, else relative to the pelvis) and the knee's flexion.
struct LegAngles {
  std::vector<double> thigh, knee;
};

LegAngles calcLegAngles(const MotionTable& table, const MotionColumns& columns) {
  const double toRad = table.inDegrees ? kDegToRad : 1.0;
  const std::vector<double>& hip = table.column(columns.hip);
  const std::vector<double>& knee = table.column(columns.knee);
  const std::vector<double>* tilt = columns.pelvisTilt.empty() ? nullptr : &table.column(columns.pelvisTilt);
  LegAngles a;
  for (std::size_t k = 0; k < table.rows(); ++k) {
    a.thigh.push_back(columns.hipSign * hip[k] * toRad + columns.hipOffset + (tilt ? (*tilt)[k] * toRad : 0.0));
    a.knee.push_back(columns.kneeSign * knee[k] * toRad + columns.kneeOffset);
  }
  return a;
}

/// Least knee range of a file holding a swing, rad: a walking knee flexes some 60-70 deg in
/// a swing and under 25 deg in a stance (the OpenSim walk: 70 and 21-25 deg), so a range
/// under 30 deg is stance only.
constexpr double kMinSwingKneeRange = 30 * kDegToRad;

/// Rows of the knee's swing peaks: in each run of rows flexed beyond the middle of the
/// file's knee range, the most flexed (a stance's loading flexion stays well below it).
std::vector<std::size_t> findSwingPeaks(const std::vector<double>& knee) {
  const auto [lo, hi] = std::minmax_element(knee.begin(), knee.end());
  const double middle = 0.5 * (*lo + *hi);
  std::vector<std::size_t> peaks;
  if (*hi - *lo < kMinSwingKneeRange) return peaks;
  for (std::size_t k = 0; k < knee.size(); ++k) {
    if (knee[k] <= middle) continue;
    std::size_t top = k;
    for (; k < knee.size() && knee[k] > middle; ++k)
      if (knee[k] > knee[top]) top = k;
    peaks.push_back(top);
  }
  return peaks;
}

/// Toe-off before the swing peak at row `peak`: the fastest knee flexion on the rise to
/// it from the stance's last extension minimum. nullopt if that rise starts at the first row
/// (the swing is cut by the file's start). A peak on the last row is the file's end mid-rise.
std::optional<double> findKinematicToeOff(const std::vector<double>& t, const std::vector<double>& knee, std::size_t peak) {
  std::size_t start = peak;
  while (start > 0 && knee[start - 1] < knee[start]) --start;
  // Central differences need a row either side; a peak on the last row still has its rise.
  const std::size_t last = std::min(peak, knee.size() - 2);
  if (start == 0 || last < start + 2) return std::nullopt;
  std::vector<double> rate(knee.size(), 0.0);
  for (std::size_t k = start; k <= last; ++k) rate[k] = (knee[k + 1] - knee[k - 1]) / (t[k + 1] - t[k - 1]);
  std::size_t fastest = start + 1;
  for (std::size_t k = start + 1; k < last; ++k)
    if (rate[k] > rate[fastest]) fastest = k;
  if (rate[last] > rate[fastest]) return std::nullopt;  // still speeding up where the file ends
  return vertexTime(t, rate, fastest);
}

/// Heel contact after the swing peak at row `peak`, before row `end`: the first maximum of
/// the ankle's forward distance from the hip, sin(thigh) + sin(thigh - knee) in thigh
/// lengths (thigh and shank of equal length). nullopt if the file ends first.
std::optional<double> findKinematicHeelContact(const std::vector<double>& t, const LegAngles& a, std::size_t peak,
                                               std::size_t end) {
  const auto forward = [&](std::size_t k) { return std::sin(a.thigh[k]) + std::sin(a.thigh[k] - a.knee[k]); };
  std::vector<double> x(t.size(), 0.0);
  for (std::size_t k = peak; k < end && k < t.size(); ++k) x[k] = forward(k);
  for (std::size_t k = peak + 1; k + 1 < end && k + 1 < t.size(); ++k)
    if (x[k] >= x[k - 1] && x[k] > x[k + 1]) return vertexTime(t, x, k);
  return std::nullopt;
}

/// Toe-off and heel contact from the joint angles alone (docs/swing-events.md). Toe-off:
/// the knee's fastest flexion on its rise into the swing (an assumption, checked against the
/// force plates). Heel contact: after Zeni et al. 2008 (Gait Posture 27:710), the heel's
/// most forward position relative to the pelvis, with the ankle for the heel, placed by the
/// thigh's and the knee's angles with thigh and shank of equal length (Winter 2009,
/// Biomechanics and Motor Control of Human Movement, Table 4.1: 0.245 H and 0.246 H).
std::vector<Event> calcKinematicEvents(const MotionTable& table, const MotionColumns& columns) {
  const LegAngles a = calcLegAngles(table, columns);
  const std::vector<double>& t = table.columns.front();
  std::vector<Event> events;
  if (t.size() < 3) return events;
  const std::vector<std::size_t> peaks = findSwingPeaks(a.knee);
  for (std::size_t p = 0; p < peaks.size(); ++p) {
    if (auto toeOff = findKinematicToeOff(t, a.knee, peaks[p])) events.push_back({*toeOff, Kind::ToeOff, "kinematics"});
    const std::size_t end = p + 1 < peaks.size() ? peaks[p + 1] : t.size();
    if (auto heel = findKinematicHeelContact(t, a, peaks[p], end)) events.push_back({*heel, Kind::HeelContact, "kinematics"});
  }
  return events;
}

/// The events: the force's within the kinematics' time, and the kinematics' where the force
/// does not decide (no force event of the kind within kEventMatchS, and not inside the
/// force's time by more than that), in time order.
std::vector<Event> mergeEvents(const std::vector<Event>& force, const std::vector<Event>& kinematic, double t0, double t1,
                               double forceStart, double forceEnd) {
  std::vector<Event> events;
  for (const Event& e : force)
    if (e.time >= t0 && e.time <= t1) events.push_back(e);
  for (const Event& e : kinematic) {
    const bool matched = std::any_of(force.begin(), force.end(), [&](const Event& f) {
      return f.kind == e.kind && std::abs(f.time - e.time) <= kEventMatchS;
    });
    const bool decidedByForce = e.time > forceStart + kEventMatchS && e.time < forceEnd - kEventMatchS;
    if (!matched && !decidedByForce) events.push_back(e);
  }
  std::sort(events.begin(), events.end(), [](const Event& a, const Event& b) { return a.time < b.time; });
  return events;
}

/// Each toe-off followed directly by a heel contact.
std::vector<FoundSwing> pairSwings(const std::vector<Event>& events) {
  std::vector<FoundSwing> swings;
  for (std::size_t i = 0; i + 1 < events.size(); ++i)
    if (events[i].kind == Kind::ToeOff && events[i + 1].kind == Kind::HeelContact)
      swings.push_back({events[i].time, events[i + 1].time, events[i].source, events[i + 1].source});
  return swings;
}

SwingEventTimes splitByKind(const std::vector<Event>& events) {
  SwingEventTimes out;
  for (const Event& e : events) (e.kind == Kind::ToeOff ? out.toeOffs : out.heelContacts).push_back(e.time);
  return out;
}

void checkThreshold(const MotionTable& grf, const GrfSettings& settings) {
  if (!(settings.thresholdN > 0) || !std::isfinite(settings.thresholdN))
    throw InputError(grf.path + ": " + settings.verticalForce + ": threshold_N: expected a positive force, N (got " +
                     formatNumber(settings.thresholdN) + ")");
}

}  // namespace

SwingEventTimes findGrfEvents(const MotionTable& grf, const GrfSettings& settings) {
  checkThreshold(grf, settings);
  return splitByKind(calcGrfEvents(grf, settings));
}

SwingEventTimes findKinematicEvents(const MotionTable& kinematics, const MotionColumns& columns) {
  return splitByKind(calcKinematicEvents(kinematics, columns));
}

std::vector<FoundSwing> findSwings(const MotionTable& kinematics, const MotionColumns& columns,
                                   const std::optional<GrfSettings>& grf) {
  if (grf) return findSwings(kinematics, columns, readMotionTable(grf->path), *grf);
  if (kinematics.rows() == 0) return {};
  const std::vector<double>& t = kinematics.columns.front();
  return pairSwings(mergeEvents({}, calcKinematicEvents(kinematics, columns), t.front(), t.back(), 0, 0));
}

std::vector<FoundSwing> findSwings(const MotionTable& kinematics, const MotionColumns& columns, const MotionTable& grf,
                                   const GrfSettings& settings) {
  const std::size_t force = grf.index(settings.verticalForce);  // throws, listing the labels, if missing
  checkThreshold(grf, settings);
  const std::vector<Event> kinematic = calcKinematicEvents(kinematics, columns);  // checks the hip and knee labels
  const std::vector<double>& t = kinematics.columns.front();
  const std::vector<double>& g = grf.columns.front();
  if (t.empty() || grf.columns[force].empty()) return {};
  if (g.back() <= t.front() || g.front() >= t.back())
    throw InputError(grf.path + ":" + std::to_string(grf.rowLines.front()) + ": time: expected times overlapping the kinematics' (" +
                     kinematics.path + ": " + formatNumber(t.front()) + " to " + formatNumber(t.back()) + " s) (got " +
                     formatNumber(g.front()) + " to " + formatNumber(g.back()) + " s)");
  return pairSwings(mergeEvents(calcGrfEvents(grf, settings), kinematic, t.front(), t.back(), g.front(), g.back()));
}

}  // namespace swingsim
