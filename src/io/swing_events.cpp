#include "io/swing_events.h"

#include <algorithm>
#include <cmath>

#include "core/input_error.h"
#include "core/text_format.h"
#include "core/units.h"
#include "numerics/metrics.h"

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
      events.erase(events.begin() + static_cast<std::ptrdiff_t>(i),
                   events.begin() + static_cast<std::ptrdiff_t>(i + 2));
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

/// Where a swing peak must reach in the file's knee range (0 its least flexion, 1 its most):
/// on the public trials the stance's loading flexion reaches 0.31-0.52 of it in running (the
/// knee flexes 40-58 deg under load) and below 0.35 in walking, each swing's peak 0.90-1.0.
constexpr double kSwingPeakLevel = 0.65;

/// Rows of the knee's swing peaks: in each run of rows flexed beyond kSwingPeakLevel of the
/// file's knee range, the most flexed (a stance's loading flexion stays below it).
std::vector<std::size_t> findSwingPeaks(const std::vector<double>& knee) {
  std::vector<std::size_t> peaks;
  if (knee.empty()) return peaks;
  const auto [lo, hi] = std::minmax_element(knee.begin(), knee.end());
  const double middle = *lo + kSwingPeakLevel * (*hi - *lo);
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

/// The median time between successive swing peaks (one stride), s; nullopt with fewer than two.
std::optional<double> medianStride(const std::vector<double>& t, const std::vector<std::size_t>& peaks) {
  if (peaks.size() < 2) return std::nullopt;
  std::vector<double> strides;
  for (std::size_t i = 1; i < peaks.size(); ++i) strides.push_back(t[peaks[i]] - t[peaks[i - 1]]);
  return calcMedian(strides);
}

std::string ms(double s) { return fmt("%.1f ms", s * 1000); }
std::string seconds(double s) { return fmt("%.4f s", s); }

struct GaitChoice {
  Gait gait = Gait::kWalking;
  std::string basis = "";
  /// A stated gait that detection (stride, or one swing's knee peak) contradicts: what to
  /// check ("" if none).
  std::string contradiction = "";
};

GaitChoice detectGait(const std::vector<double>& t, const std::vector<double>& knee,
                      const std::vector<std::size_t>& peaks);

/// The stated gait, else running for a stride under kRunningStrideS (or, with one swing, a
/// knee peak above kRunningKneePeak), else walking. A stated gait that detection
/// contradicts is kept, and the contradiction said.
GaitChoice chooseGait(const std::vector<double>& t, const std::vector<double>& knee,
                      const std::vector<std::size_t>& peaks, std::optional<Gait> stated) {
  if (!stated) return detectGait(t, knee, peaks);
  GaitChoice out{*stated, "stated", ""};
  if (!peaks.empty()) {
    const GaitChoice detected = detectGait(t, knee, peaks);
    const std::string basis = detected.basis.rfind("detected: ", 0) == 0 ? detected.basis.substr(10) : detected.basis;
    if (detected.gait != *stated)
      out.contradiction = std::string("the gait is stated as ") + gaitName(*stated) + " but the trial looks like " +
                          gaitName(detected.gait) + " (" + basis + "): its " + gaitName(*stated) +
                          " event rules may misplace toe-off; check the stated gait";
  }
  return out;
}

GaitChoice detectGait(const std::vector<double>& t, const std::vector<double>& knee,
                      const std::vector<std::size_t>& peaks) {
  if (const auto stride = medianStride(t, peaks)) {
    const bool running = *stride < kRunningStrideS;
    return {running ? Gait::kRunning : Gait::kWalking,
            "detected: median stride " + formatNumber(std::round(*stride * 1000) / 1000) + " s, " +
                (running ? "under " : "over ") + formatNumber(kRunningStrideS) + " s"};
  }
  if (peaks.empty()) return {Gait::kWalking, "no swing to detect it from"};
  const double peak = knee[peaks.front()];
  const bool running = peak > kRunningKneePeak;
  return {running ? Gait::kRunning : Gait::kWalking,
          "detected from one swing: knee peak " + formatNumber(std::round(peak * kRadToDeg)) + " deg, " +
              (running ? "above " : "below ") + formatNumber(std::round(kRunningKneePeak * kRadToDeg)) +
              " deg (no stride to measure; state the gait if this is wrong)"};
}

/// The row where the knee's rise into the swing peak at `peak` starts (the stance's last
/// extension minimum); 0 if the rise starts at the first row (the swing is cut by the file's start).
std::size_t riseStart(const std::vector<double>& knee, std::size_t peak) {
  std::size_t start = peak;
  while (start > 0 && knee[start - 1] < knee[start]) --start;
  return start;
}

/// Walking toe-off before the swing peak at row `peak`: the fastest knee flexion on the rise
/// to it from the stance's last extension minimum. A rise cut by the file's start counts when
/// its fastest flexion lies past the file's first rate (the knee still speeding up there).
/// nullopt if it does not, or if the rise is still speeding up where the file ends.
std::optional<double> findWalkingToeOff(const std::vector<double>& t, const std::vector<double>& knee,
                                        std::size_t peak) {
  const std::size_t start = riseStart(knee, peak);
  // Central differences need a row either side; a peak on the last row still has its rise.
  const std::size_t first = std::max<std::size_t>(start, 1);
  const std::size_t last = std::min(peak, knee.size() - 2);
  if (knee.size() < 3 || last < first + 2) return std::nullopt;
  std::vector<double> rate(knee.size(), 0.0);
  for (std::size_t k = first; k <= last; ++k) rate[k] = (knee[k + 1] - knee[k - 1]) / (t[k + 1] - t[k - 1]);
  std::size_t fastest = first + 1;
  for (std::size_t k = first + 1; k < last; ++k)
    if (rate[k] > rate[fastest]) fastest = k;
  if (rate[last] > rate[fastest]) return std::nullopt;                  // still speeding up where the file ends
  if (start == 0 && rate[first] >= rate[fastest]) return std::nullopt;  // the fastest may lie before the file
  return vertexTime(t, rate, fastest);
}

/// Running toe-off before the swing peak at row `peak`: the knee's extension minimum at the
/// end of the stance, where its rise into the swing starts (after Fellin et al. 2010, J Sci
/// Med Sport 13:646, toe-off at peak knee extension). nullopt if that is the first row.
std::optional<double> findRunningToeOff(const std::vector<double>& t, const std::vector<double>& knee,
                                        std::size_t peak) {
  const std::size_t start = riseStart(knee, peak);
  if (start == 0 || start + 1 >= knee.size()) return std::nullopt;
  return vertexTime(t, knee, start);
}

/// Walking heel contact after the swing peak at row `peak`, before row `end`: the first
/// maximum of the ankle's forward distance from the hip, sin(thigh) + sin(thigh - knee) in
/// thigh lengths (thigh and shank of equal length). nullopt if the file ends first.
std::optional<double> findWalkingHeelContact(const std::vector<double>& t, const LegAngles& a, std::size_t peak,
                                             std::size_t end) {
  const auto forward = [&](std::size_t k) { return std::sin(a.thigh[k]) + std::sin(a.thigh[k] - a.knee[k]); };
  std::vector<double> x(t.size(), 0.0);
  for (std::size_t k = peak; k < end && k < t.size(); ++k) x[k] = forward(k);
  for (std::size_t k = peak + 1; k + 1 < end && k + 1 < t.size(); ++k)
    if (x[k] >= x[k - 1] && x[k] > x[k + 1]) return vertexTime(t, x, k);
  return std::nullopt;
}

/// Running heel contact after the swing peak at row `peak`, before row `end`: the knee's
/// first extension minimum (the end of its extension in the late swing; it flexes again as
/// the foot lands). nullopt if the file ends first.
std::optional<double> findRunningHeelContact(const std::vector<double>& t, const std::vector<double>& knee,
                                             std::size_t peak, std::size_t end) {
  for (std::size_t k = peak + 1; k + 1 < end && k + 1 < t.size(); ++k)
    if (knee[k] <= knee[k - 1] && knee[k] < knee[k + 1]) return vertexTime(t, knee, k);
  return std::nullopt;
}

/// Why the first swing (peak at row `peak`, its toe-off `toeOff` with the bias removed) might
/// be counted by the force plates and not by the kinematics, or the other way round; empty
/// when it cannot. A peak on the first row is a swing already past its toe-off; so is a rise
/// cut by the file's start that reaches its peak sooner than any later swing of the file
/// reaches its own from toe-off (`shortestRise`, s, less the rules' accuracy).
std::string describeLeadingAmbiguity(const std::vector<double>& t, const std::vector<double>& knee, std::size_t peak,
                                     const std::optional<double>& toeOff, std::optional<double> shortestRise,
                                     bool running) {
  const double accuracy = running ? kRunningAccuracyS : kWalkingAccuracyS;
  if (peak == 0) return "";
  if (!toeOff) {
    if (riseStart(knee, peak) != 0) return "";
    if (shortestRise && t[peak] - t.front() < *shortestRise - accuracy) return "";
    return "the file starts while the knee rises into its first swing (peak at " + seconds(t[peak]) +
           "): whether that swing's toe-off lies inside the file the kinematics cannot tell";
  }
  if (*toeOff >= t.front() + accuracy) return "";
  return "the first swing's toe-off (" + seconds(*toeOff) + ") lies within the kinematic rules' accuracy (" +
         ms(accuracy) + ") of the file's start: the force plates could place it before the file";
}

/// Kinematic events with the rule's bias removed, the swing peaks and the gait.
struct KinematicEvents {
  std::vector<Event> events;
  /// Why the first swing's number is not the force's to give, when it may not be: its toe-off
  /// lies so near the file's start (within the rules' accuracy, or its rise cut by the start
  /// without a toe-off placed) that the force plates could count the swing or not. Empty when
  /// the numbering is sure.
  std::string numberingAmbiguity;
  std::vector<double> peakTimes;
  std::optional<double> stride;  ///< s
  GaitChoice gait;
};

/// Toe-off and heel contact from the joint angles alone (docs/swing-events.md). Walking:
/// toe-off at the knee's fastest flexion on its rise into the swing (an assumption, checked
/// against the force plates); heel contact after Zeni et al. 2008 (Gait Posture 27:710), the
/// heel's most forward position relative to the pelvis, with the ankle for the heel, placed
/// by the thigh's and the knee's angles with thigh and shank of equal length (Winter 2009,
/// Biomechanics and Motor Control of Human Movement, Table 4.1: 0.245 H and 0.246 H).
/// Running: toe-off at the knee's extension minimum before its rise, heel contact at its
/// extension minimum after the swing peak. Each with its measured bias removed.
KinematicEvents calcKinematicEvents(const MotionTable& table, const MotionColumns& columns,
                                    std::optional<Gait> stated) {
  const LegAngles a = calcLegAngles(table, columns);
  const std::vector<double>& t = table.columns.front();
  KinematicEvents out;
  const std::vector<std::size_t> peaks = t.size() < 3 ? std::vector<std::size_t>{} : findSwingPeaks(a.knee);
  out.gait = chooseGait(t, a.knee, peaks, stated);
  out.stride = medianStride(t, peaks);
  const bool running = out.gait.gait == Gait::kRunning;
  const double toeOffBias = running ? kRunningToeOffBiasS : kWalkingToeOffBiasS;
  const double heelBias = running ? kRunningHeelContactBiasS : kWalkingHeelContactBiasS;
  std::optional<double> firstToeOff,
      shortestRise;  // the first swing's toe-off; the later swings' least toe-off to peak
  for (std::size_t p = 0; p < peaks.size(); ++p) {
    out.peakTimes.push_back(t[peaks[p]]);
    auto toeOff = running ? findRunningToeOff(t, a.knee, peaks[p]) : findWalkingToeOff(t, a.knee, peaks[p]);
    if (toeOff) {
      *toeOff -= toeOffBias;
      out.events.push_back({*toeOff, Kind::ToeOff, "kinematics"});
      const double rise = t[peaks[p]] - *toeOff;
      if (p > 0) shortestRise = std::min(shortestRise.value_or(rise), rise);
    }
    if (p == 0) firstToeOff = toeOff;
    const std::size_t end = p + 1 < peaks.size() ? peaks[p + 1] : t.size();
    const auto heel =
        running ? findRunningHeelContact(t, a.knee, peaks[p], end) : findWalkingHeelContact(t, a, peaks[p], end);
    if (heel) out.events.push_back({*heel - heelBias, Kind::HeelContact, "kinematics"});
  }
  if (!peaks.empty())
    out.numberingAmbiguity = describeLeadingAmbiguity(t, a.knee, peaks[0], firstToeOff, shortestRise, running);
  return out;
}

/// Each toe-off followed directly by a heel contact.
std::vector<FoundSwing> pairSwings(const std::vector<Event>& events) {
  std::vector<FoundSwing> swings;
  for (std::size_t i = 0; i + 1 < events.size(); ++i)
    if (events[i].kind == Kind::ToeOff && events[i + 1].kind == Kind::HeelContact)
      swings.push_back({events[i].time, events[i + 1].time, events[i].source, events[i + 1].source, {}, {}});
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

/// "" if the force crosses `thresholdN` at all; else what to fix, with the peak (a threshold
/// above the peak found no event, and the run said only "no complete swing", rc 0).
std::string checkThresholdBelowPeak(const std::vector<double>& force, double thresholdN) {
  if (force.empty()) return "";
  const double peak = *std::max_element(force.begin(), force.end());
  if (peak >= thresholdN) return "";
  return "threshold_N: expected a threshold below the force's peak, " + formatNumber(peak) + " N (got " +
         formatNumber(thresholdN) + " N: --threshold-N, a study's threshold_N)";
}

/// The median step of a time column, s; 0 for fewer than two rows.
double medianStep(const std::vector<double>& t) {
  std::vector<double> steps;
  for (std::size_t k = 1; k < t.size(); ++k) steps.push_back(t[k] - t[k - 1]);
  return steps.empty() ? 0 : calcMedian(steps);
}

/// The event of `kind` in `events` nearest to `time`; nullptr if there is none.
const Event* findNearest(const std::vector<Event>& events, Kind kind, double time) {
  const Event* nearest = nullptr;
  for (const Event& e : events)
    if (e.kind == kind && (!nearest || std::abs(e.time - time) < std::abs(nearest->time - time))) nearest = &e;
  return nearest;
}

/// A force plate's zero drifts by a few newtons; a vertical force that pulls below zero by
/// more than this (and a tenth of its peak) is not a vertical force, N.
constexpr double kMaxForceOffsetN = 20;

/// Steps of one clock that agree with another's to round-off of the written times.
constexpr double kSameRateFraction = 1.05;

/// What a force file must hold before an event is taken from it: a rate at least the
/// kinematics', a time in seconds on their clock, a vertical force in newtons. "" if it
/// holds, else what was found (for the message after "file: column: ").
std::string checkForceFile(const MotionTable& grf, const std::vector<double>& force, const MotionTable& kinematics) {
  const std::vector<double>& g = grf.columns.front();
  const std::vector<double>& t = kinematics.columns.front();
  const double forceStep = medianStep(g), frame = medianStep(t);
  if (forceStep > frame * kSameRateFraction) {
    std::string hint;
    if (forceStep > 0.1 && g.front() / 1000 < t.back() && g.back() / 1000 > t.front())
      hint = "; its time, read as ms, would overlap the kinematics': is the time column in ms? OpenSim's is in s";
    return "expected a force sampled at least as often as the kinematics (" + formatNumber(std::round(1 / frame)) +
           " Hz), so that an event lands within a frame (got a step of " + formatNumber(forceStep) + " s, " +
           formatNumber(1 / forceStep) + " Hz" + hint + ")";
  }
  // The force over the kinematics' time (the whole file if they do not overlap).
  double peak = -1e300, lowest = 1e300;
  bool any = false;
  for (std::size_t k = 0; k < g.size(); ++k)
    if (g[k] >= t.front() && g[k] <= t.back()) {
      peak = std::max(peak, force[k]);
      lowest = std::min(lowest, force[k]);
      any = true;
    }
  if (!any) return "";  // the clock check after this says what is wrong
  if (peak < kMinStancePeakN && lowest < -kMinStancePeakN)
    return "expected a vertical force, positive upwards, N: a stance peaks at 1-3 body weights (got " +
           formatNumber(lowest) + " to " + formatNumber(peak) + " N: negated? OpenSim's vertical force pushes up, +y)";
  // A vertical force pulls below zero by no more than its offset; a horizontal one by as much as it pushes.
  if (lowest < -std::max(kMaxForceOffsetN, 0.1 * peak))
    return "expected a vertical force, which never pulls the foot down (got " + formatNumber(lowest) + " to " +
           formatNumber(peak) + " N: a horizontal component, e.g. the fore-aft force, or a lab frame with z up?)";
  if (peak < kMinStancePeakN)
    return "expected a vertical force in newtons: a stance peaks at 1-3 body weights, at least " +
           formatNumber(kMinStancePeakN) + " N (got a peak of " + formatNumber(peak) + " N over the kinematics' time" +
           (peak > 0 && peak * 1000 >= kMinStancePeakN ? ": in kN?"
            : peak <= 0                                ? ": no load at all"
                                                       : "") +
           ")";
  if (peak > kMaxStancePeakN)
    return "expected a vertical force in newtons: a stance peaks at 1-3 body weights, at most " +
           formatNumber(kMaxStancePeakN) + " N (got a peak of " + formatNumber(peak) + " N: another unit?)";
  return "";
}

/// Each force event inside the kinematics' time [t0, t1] with the kinematic event of its kind
/// nearest to it, where that lies within 0.6 strides (elsewhere the kinematics see no such event).
std::vector<std::pair<const Event*, const Event*>> pairWithKinematicEvents(const std::vector<Event>& force,
                                                                           const KinematicEvents& kin, double t0,
                                                                           double t1) {
  const double stride = kin.stride.value_or(kin.gait.gait == Gait::kRunning ? 0.7 : 1.1);
  std::vector<std::pair<const Event*, const Event*>> pairs;
  for (const Event& f : force) {
    if (f.time < t0 || f.time > t1) continue;
    const Event* nearest = findNearest(kin.events, f.kind, f.time);
    if (nearest && std::abs(nearest->time - f.time) <= 0.6 * stride) pairs.emplace_back(&f, nearest);
  }
  return pairs;
}

/// The first way the force's events contradict the kinematics', "" if none: an event more
/// than kEventToleranceS from the kinematic one of its kind (within 0.6 strides), a knee swing
/// peak inside the force's stance, a force swing without a knee swing peak.
std::string findContradiction(const std::vector<Event>& force, bool loadedAtStart, const KinematicEvents& kin,
                              double t0, double t1, double forceStart, double forceEnd) {
  for (const auto& [f, nearest] : pairWithKinematicEvents(force, kin, t0, t1))
    if (std::abs(nearest->time - f->time) > kEventToleranceS)
      return std::string(f->kind == Kind::ToeOff ? "toe-off" : "heel contact") + " at " + seconds(f->time) + " is " +
             ms(f->time - nearest->time) + " from the kinematics' (" + seconds(nearest->time) + "; at most " +
             ms(kEventToleranceS) + " expected)";
  // Stance from the force at a time: as at the file's first row, then as each event says (a
  // force that never falls below the threshold, e.g. both feet on one plate, is stance throughout).
  const auto inStance = [&](double time) {
    bool stance = loadedAtStart;
    for (const Event& f : force) {
      if (f.time > time) break;
      stance = f.kind == Kind::HeelContact;
    }
    return stance;
  };
  for (double peak : kin.peakTimes)
    if (peak > forceStart && peak < forceEnd && inStance(peak))
      return "the knee's swing peak at " + seconds(peak) + " falls in a stance of the force" +
             (force.empty() ? " (the force never falls below the threshold: both feet on one plate, or a total force?)"
                            : "");
  for (std::size_t i = 0; i + 1 < force.size(); ++i) {
    if (force[i].kind != Kind::ToeOff || force[i].time < t0 || force[i + 1].time > t1) continue;
    const bool hasPeak = std::any_of(kin.peakTimes.begin(), kin.peakTimes.end(),
                                     [&](double p) { return p > force[i].time && p < force[i + 1].time; });
    if (!hasPeak)
      return "the force's swing " + seconds(force[i].time) + " to " + seconds(force[i + 1].time) +
             " holds no swing of the knee (no flexion peak)";
  }
  return "";
}

/// A clock offset between the force and the kinematics: every force event (at least 3 inside
/// the kinematics' time, each with a kinematic event of its kind within 0.6 stride) lies one
/// offset from its kinematic event, to within kEventToleranceS, and that offset is beyond
/// kEventToleranceS. The offset (force minus kinematics, s), or nullopt.
std::optional<double> findClockOffset(const std::vector<Event>& force, const KinematicEvents& kin, double t0,
                                      double t1) {
  std::vector<double> d;
  for (const auto& [f, nearest] : pairWithKinematicEvents(force, kin, t0, t1)) d.push_back(f->time - nearest->time);
  constexpr std::size_t kMinEvents = 3;
  if (d.size() < kMinEvents) return std::nullopt;
  std::vector<double> sorted = d;
  std::sort(sorted.begin(), sorted.end());
  const double median = sorted[sorted.size() / 2];
  if (std::abs(median) <= kEventToleranceS) return std::nullopt;
  for (double x : d)
    if (std::abs(x - median) > kEventToleranceS) return std::nullopt;
  return median;
}

/// The other leg's columns (`_r` and `_l` swapped at the end of the hip and knee labels),
/// when the file has them.
std::optional<MotionColumns> otherLegColumns(const MotionTable& table, const MotionColumns& columns) {
  const auto swap = [](const std::string& label) -> std::optional<std::string> {
    if (label.size() < 2) return std::nullopt;
    const std::string end = label.substr(label.size() - 2);
    if (end != "_r" && end != "_l") return std::nullopt;
    return label.substr(0, label.size() - 2) + (end == "_r" ? "_l" : "_r");
  };
  const auto hip = swap(columns.hip), knee = swap(columns.knee);
  if (!hip || !knee) return std::nullopt;
  for (const std::string* label : {&*hip, &*knee})
    if (std::find(table.labels.begin(), table.labels.end(), *label) == table.labels.end()) return std::nullopt;
  MotionColumns other = columns;
  other.hip = *hip;
  other.knee = *knee;
  return other;
}

/// The events: the force's within the kinematics' time, and the kinematics' outside the
/// force's time (nearer its ends than kEventToleranceS counts as inside only where the force
/// has an event of that kind there), in time order, with each force event's disagreement.
std::vector<FoundSwing> mergeEvents(const std::vector<Event>& force, const KinematicEvents& kin, double t0, double t1,
                                    double forceStart, double forceEnd) {
  std::vector<Event> events;
  for (const Event& e : force)
    if (e.time >= t0 && e.time <= t1) events.push_back(e);
  for (const Event& e : kin.events) {
    const Event* f = findNearest(force, e.kind, e.time);
    const bool matched = f && std::abs(f->time - e.time) <= kEventToleranceS;
    const bool decidedByForce = e.time > forceStart + kEventToleranceS && e.time < forceEnd - kEventToleranceS;
    if (!matched && !decidedByForce) events.push_back(e);
  }
  std::sort(events.begin(), events.end(), [](const Event& a, const Event& b) { return a.time < b.time; });
  std::vector<FoundSwing> swings = pairSwings(events);
  const auto disagreement = [&](double time, Kind kind, const std::string& source) -> std::optional<double> {
    const Event* k = findNearest(kin.events, kind, time);
    if (source != "grf" || !k || std::abs(time - k->time) > kEventToleranceS) return std::nullopt;
    return time - k->time;
  };
  for (FoundSwing& s : swings) {
    s.toeOffDisagreement = disagreement(s.toeOff, Kind::ToeOff, s.toeOffSource);
    s.heelContactDisagreement = disagreement(s.heelContact, Kind::HeelContact, s.heelContactSource);
  }
  return swings;
}

/// The list of `swings`; the kinematics' numbering ambiguity kept when `leadByKinematics`
/// (no force, or a force that starts after the kinematics), and said in its notes.
SwingList makeList(std::vector<FoundSwing> swings, const KinematicEvents& kin, const MotionTable& kinematics,
                   bool leadByKinematics = true) {
  SwingList out;
  if (leadByKinematics && !kin.numberingAmbiguity.empty()) {
    out.numberingAmbiguity = kin.numberingAmbiguity;
    out.notes.push_back(
        "swing numbers: " + kin.numberingAmbiguity + ", so a force file could number the swings one apart " +
        "from these; a study's `swing: K` on this file needs its force file (grf:) or the swing's times " +
        "(toe_off_s, heel_contact_s)");
  }
  if (!kin.gait.contradiction.empty()) out.notes.push_back(kin.gait.contradiction);
  out.swings = std::move(swings);
  out.gait = kin.gait.gait;
  out.gaitBasis = kin.gait.basis;
  out.kinematicAccuracy = out.gait == Gait::kRunning ? kRunningAccuracyS : kWalkingAccuracyS;
  out.kinematicAccuracyBeyondTwoFrames = out.kinematicAccuracy > 2 * medianStep(kinematics.columns.front());
  return out;
}

}  // namespace

const char* gaitName(Gait gait) { return gait == Gait::kRunning ? "running" : "walking"; }

SwingEventTimes findGrfEvents(const MotionTable& grf, const GrfSettings& settings) {
  checkThreshold(grf, settings);
  if (const std::string bad = checkThresholdBelowPeak(grf.column(settings.verticalForce), settings.thresholdN);
      !bad.empty())
    throw InputError(grf.path + ": " + settings.verticalForce + ": " + bad);
  return splitByKind(calcGrfEvents(grf, settings));
}

SwingEventTimes findKinematicEvents(const MotionTable& kinematics, const MotionColumns& columns,
                                    std::optional<Gait> gait) {
  return splitByKind(calcKinematicEvents(kinematics, columns, gait).events);
}

SwingList listSwings(const MotionTable& kinematics, const MotionColumns& columns, const std::optional<GrfSettings>& grf,
                     std::optional<Gait> gait) {
  if (grf) return listSwings(kinematics, columns, readMotionTable(grf->path), *grf, gait);
  checkLegKinematics(kinematics, columns);
  const KinematicEvents kin = calcKinematicEvents(kinematics, columns, gait);
  if (kinematics.rows() == 0) return makeList({}, kin, kinematics);
  const std::vector<double>& t = kinematics.columns.front();
  return makeList(mergeEvents({}, kin, t.front(), t.back(), 0, 0), kin, kinematics);
}

SwingList listSwings(const MotionTable& kinematics, const MotionColumns& columns, const MotionTable& grf,
                     const GrfSettings& settings, std::optional<Gait> gait) {
  const std::size_t force = grf.index(settings.verticalForce);  // throws, listing the labels, if missing
  checkThreshold(grf, settings);
  checkLegKinematics(kinematics, columns);
  const KinematicEvents kin = calcKinematicEvents(kinematics, columns, gait);
  const std::vector<double>& t = kinematics.columns.front();
  const std::vector<double>& g = grf.columns.front();
  if (t.empty() || grf.columns[force].empty()) return makeList({}, kin, kinematics);
  const std::string where = grf.path + ": " + settings.verticalForce + ": ";
  const auto kinematicsOnly = [&](const std::string& why) {
    SwingList out = makeList(mergeEvents({}, kin, t.front(), t.back(), 0, 0), kin, kinematics);
    out.notes.push_back("events from the kinematics, not the force (fallback_to_kinematics): " + where + why);
    return out;
  };
  if (const std::string bad = checkForceFile(grf, grf.columns[force], kinematics); !bad.empty()) {
    if (settings.fallbackToKinematics) return kinematicsOnly(bad);
    throw InputError(where + bad);
  }
  if (g.back() <= t.front() || g.front() >= t.back()) {
    const std::string bad = "time: expected times overlapping the kinematics' (" + kinematics.path + ": " +
                            formatNumber(t.front()) + " to " + formatNumber(t.back()) + " s) (got " +
                            formatNumber(g.front()) + " to " + formatNumber(g.back()) + " s)";
    if (settings.fallbackToKinematics) return kinematicsOnly(bad);
    throw InputError(grf.path + ":" + std::to_string(grf.rowLines.front()) + ": " + bad);
  }
  if (const std::string bad = checkThresholdBelowPeak(grf.columns[force], settings.thresholdN); !bad.empty()) {
    if (settings.fallbackToKinematics) return kinematicsOnly(bad);
    throw InputError(where + bad);
  }
  const std::vector<Event> forceEvents = calcGrfEvents(grf, settings);
  const bool loadedAtStart = grf.columns[force].front() >= settings.thresholdN;
  if (const std::string contradiction =
          findContradiction(forceEvents, loadedAtStart, kin, t.front(), t.back(), g.front(), g.back());
      !contradiction.empty()) {
    std::string other;
    if (const auto offset = findClockOffset(forceEvents, kin, t.front(), t.back()))
      other = ": every force event is about " + ms(std::abs(*offset)) + (*offset > 0 ? " later" : " earlier") +
              " than the kinematics' (to within " + ms(kEventToleranceS) + "), so the two files' clocks differ by " +
              "about that: shift the force file's time column by " + fmt("%+.3f", -*offset) +
              " s (or the kinematics' by " + fmt("%+.3f", *offset) + " s) so that both share one clock";
    if (const auto otherLeg = otherLegColumns(kinematics, columns); other.empty() && otherLeg) {
      const KinematicEvents otherKin = calcKinematicEvents(kinematics, *otherLeg, kin.gait.gait);
      if (findContradiction(forceEvents, loadedAtStart, otherKin, t.front(), t.back(), g.front(), g.back()).empty())
        other = "; they match the other leg's (" + otherLeg->hip + ", " + otherLeg->knee + "): is " +
                settings.verticalForce +
                " the other foot's force? (OpenSim's example files: ground_force_vy right, 1_ground_force_vy left)";
    }
    const std::string bad =
        "expected the force's stance and swing to match the leg's kinematics (" + kinematics.path + ": " + columns.hip +
        ", " + columns.knee + ", " + gaitName(kin.gait.gait) + " rules, " + kin.gait.basis +
        ") (got: " + contradiction + ")" +
        (other.empty() ? ": another trial's force file, a clock offset, the other foot's column, or the "
                         "wrong gait's rules (state it: --gait, a study's gait:)?"
                       : other);
    if (settings.fallbackToKinematics) return kinematicsOnly(bad);
    throw InputError(where + bad);
  }
  return makeList(mergeEvents(forceEvents, kin, t.front(), t.back(), g.front(), g.back()), kin, kinematics,
                  g.front() > t.front() + kEventToleranceS);
}

FoundSwing selectSwing(const SwingList& list, const MotionTable& table, const std::string& knee, int k) {
  const std::vector<FoundSwing>& swings = list.swings;
  if (!list.numberingAmbiguity.empty())
    throw InputError(
        table.path + ": swing: " + std::to_string(k) + ": " + list.numberingAmbiguity + " (" + knee + ", " +
        gaitName(list.gait) + " rules), so the force plates could number this file's swings one apart from " +
        "the kinematics: give its force file (a diagnosis study's grf:), or the swing's times instead of its number " +
        "(toe_off_s, heel_contact_s; `swingsim swings FILE` lists them)");
  if (swings.empty())
    throw InputError(table.path + ": swing: " + std::to_string(k) + ": the file holds no complete swing of " + knee +
                     " (toe-off and heel contact both inside it; " + gaitName(list.gait) + " rules, " + list.gaitBasis +
                     "); `swingsim swings FILE` lists what it finds");
  if (k < 1 || static_cast<std::size_t>(k) > swings.size()) {
    std::string found;
    for (std::size_t i = 0; i < swings.size(); ++i)
      found += (i ? ", " : "") + fmt("%zu: %.4f-%.4f s", i + 1, swings[i].toeOff, swings[i].heelContact);
    throw InputError(table.path + ": swing: expected a swing number from 1 to " + std::to_string(swings.size()) +
                     " (the complete swings found: " + found + "; `swingsim swings FILE` lists them) (got " +
                     std::to_string(k) + ")");
  }
  return swings[static_cast<std::size_t>(k - 1)];
}

std::vector<FoundSwing> findSwings(const MotionTable& kinematics, const MotionColumns& columns,
                                   const std::optional<GrfSettings>& grf) {
  return listSwings(kinematics, columns, grf).swings;
}

std::vector<FoundSwing> findSwings(const MotionTable& kinematics, const MotionColumns& columns, const MotionTable& grf,
                                   const GrfSettings& settings) {
  return listSwings(kinematics, columns, grf, settings).swings;
}

}  // namespace swingsim
