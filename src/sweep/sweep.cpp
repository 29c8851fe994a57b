#include "sweep/sweep.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <limits>
#include <map>
#include <mutex>
#include <thread>

#include <sys/resource.h>
#include <unistd.h>

#include "core/input_error.h"
#include "sweep/burkett_published.h"
#include "swing/knee_setup.h"

namespace swingsim {

std::string studyKneeModelPath(const SweepStudy& study, const Participant& p) {
  return study.kneeModelOverride.empty() ? p.kneeModelPath : study.kneeModelOverride;
}

const KneeModel& findStudyKneeModel(const SweepStudy& study, const Participant& p) {
  const std::string path = studyKneeModelPath(study, p);
  const auto model = study.kneeModels.find(path);
  if (model == study.kneeModels.end())
    throw RunError("sweep " + study.name + ": participant " + p.name + ": knee model " + path +
                   " was not loaded with the study");
  return model->second;
}

std::vector<std::thread> startWorkerThreads(int threads, const std::function<void()>& worker) {
  std::vector<std::thread> pool;
  for (int t = 0; t < threads; ++t) {
    try {
      pool.emplace_back(worker);
    } catch (const std::exception& e) {
      // std::system_error (EAGAIN) under a memory, address-space or process limit (ulimit -v,
      // ulimit -u, a container's pids.max): fewer threads do the same work, only slower.
      std::fprintf(stderr, "swingsim: could start only %d of %d worker threads (%s); continuing with %s\n", t, threads,
                   e.what(),
                   t > 0 ? (std::to_string(t) + (t == 1 ? " thread" : " threads")).c_str() : "the main thread alone");
      break;
    }
  }
  return pool;
}

namespace {

// Address space a worker thread takes (measured with `ulimit -v` unset: peak VmSize 120 MB
// with one worker, 193 MB with two, 636 MB with eight: about 74 MB each, glibc's 64 MB
// malloc arena and the 8 MB stack), with room for its swing's own allocations.
constexpr std::uint64_t kWorkerAddressSpace = 80ull << 20;
// Address space kept free for the calling thread's own work (reports, JSON).
constexpr std::uint64_t kCallerAddressSpace = 64ull << 20;

// The worker threads an address-space limit (ulimit -v, RLIMIT_AS) leaves room for, at most
// `wanted`: (limit - what the process maps now - the caller's share) / kWorkerAddressSpace.
// No limit: `wanted`. Says so on stderr when it caps.
int capThreadsToAddressSpace(int wanted) {
  rlimit limit{};
  if (getrlimit(RLIMIT_AS, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return wanted;
  std::uint64_t pages = 0;
  {
    std::FILE* statm = std::fopen("/proc/self/statm", "r");
    if (!statm) return wanted;
    unsigned long long size = 0;
    if (std::fscanf(statm, "%llu", &size) == 1) pages = size;
    std::fclose(statm);
  }
  const std::uint64_t mapped = pages * static_cast<std::uint64_t>(sysconf(_SC_PAGESIZE));
  const std::uint64_t cap = static_cast<std::uint64_t>(limit.rlim_cur);
  const std::uint64_t room = cap > mapped + kCallerAddressSpace ? cap - mapped - kCallerAddressSpace : 0;
  const int fits =
      static_cast<int>(std::min<std::uint64_t>(room / kWorkerAddressSpace, static_cast<std::uint64_t>(wanted)));
  if (fits < wanted)
    std::fprintf(
        stderr,
        "swingsim: the address-space limit (ulimit -v %llu kB) leaves room for %d of %d worker threads; "
        "continuing with %s\n",
        static_cast<unsigned long long>(cap >> 10), fits, wanted,
        fits > 0 ? (std::to_string(fits) + (fits == 1 ? " thread" : " threads")).c_str() : "the main thread alone");
  return fits;
}

}  // namespace

int runParallelJobs(int total, int jobs, const std::function<void(int)>& runOne,
                    const std::function<void(int, int)>& progress, const volatile bool* stopFlag) {
  std::atomic<int> next{0}, done{0}, running{0};
  std::atomic<bool> failed{false};
  std::mutex mutex;            // guards failure
  std::exception_ptr failure;  // the first exception a job threw, rethrown by the calling thread
  auto worker = [&] {
    for (;;) {
      if ((stopFlag && *stopFlag) || failed.load()) break;
      const int k = next.fetch_add(1);
      if (k >= total) break;
      try {
        runOne(k);
        done.fetch_add(1);
      } catch (...) {
        // Never out of the thread (std::terminate): the other workers stop after their job
        // and the calling thread rethrows it (std::bad_alloc: main's out-of-memory message).
        const std::lock_guard<std::mutex> lock(mutex);
        if (!failure) failure = std::current_exception();
        failed = true;
        break;
      }
    }
    running.fetch_sub(1);
  };
  int threads = jobs > 0 ? jobs : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  threads = capThreadsToAddressSpace(std::min(threads, std::max(1, total)));
  // Workers pull jobs by index; the calling thread only reports progress.
  running = threads;
  std::vector<std::thread> pool = startWorkerThreads(threads, worker);
  running.fetch_sub(threads - static_cast<int>(pool.size()));
  while (progress && running.load() > 0 && done.load() < total && !(stopFlag && *stopFlag)) {
    progress(done.load(), total);
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  for (auto& t : pool) t.join();
  // Not one thread could start: the calling thread does the work (no progress bar meanwhile).
  if (pool.empty()) {
    running = 1;
    worker();
  }
  if (failure) std::rethrow_exception(failure);
  if (progress) progress(done.load(), total);
  return done.load();
}

std::vector<double> sweepLowerings(const SweepStudy& study, const Participant& p) {
  const double cap = std::min(study.loweringMax, calcMaxLowering(p));
  std::vector<double> out;
  // Integer steps, so 0.1 is exactly 10 steps of 0.01 and results do not drift.
  for (int i = 0;; ++i) {
    const double d = std::round(i * study.loweringStep * 1e6) / 1e6;
    if (d > cap + 1e-9) break;
    out.push_back(d);
  }
  if (study.includePublishedLowerings) {
    if (const PublishedParticipant* pub = findPublished(p.name)) {
      for (const auto& row : pub->table4) {
        bool onGrid = false;
        for (double d : out) onGrid = onGrid || std::fabs(d - row.lowering) < 1e-9;
        if (!onGrid && row.lowering <= calcMaxLowering(p) + 1e-9) out.push_back(row.lowering);
      }
      std::sort(out.begin(), out.end());
    }
  }
  return out;
}

std::vector<double> sweepGridLowerings(const SweepStudy& study, const Participant& p) {
  SweepStudy grid;
  grid.loweringStep = study.loweringStep;
  grid.loweringMax = study.loweringMax;
  grid.includePublishedLowerings = false;
  return sweepLowerings(grid, p);
}

std::uint64_t countSweepSwings(const SweepStudy& study) {
  std::vector<double> distances = study.addedMassDistances;
  std::sort(distances.begin(), distances.end());
  const auto masses = static_cast<std::uint64_t>(
      std::count_if(study.addedMasses.begin(), study.addedMasses.end(), [](double m) { return m > 0; }));
  std::uint64_t swings = 0;
  for (const Participant& p : study.participants) {
    for (double d : sweepLowerings(study, p)) {
      // The distances at most shank - d below the knee, as runSweep places them.
      const auto fitting = static_cast<std::uint64_t>(
          std::upper_bound(distances.begin(), distances.end(), p.shank.length - d) - distances.begin());
      swings += 1 + masses * fitting;
    }
  }
  return swings;
}

namespace {

struct Job {
  std::size_t participant;
  bool withMass;
  std::size_t index;  // into points or massPoints
};

// A participant's sweep before it runs: its name, Burkett's rows, the lowering cap and the
// note when the cap is below the study's largest lowering.
ParticipantSweep makeParticipantSweep(const SweepStudy& study, const Participant& p) {
  ParticipantSweep ps;
  ps.name = p.name;
  ps.published = findPublished(p.name);
  ps.loweringCap = std::min(study.loweringMax, calcMaxLowering(p));
  if (study.loweringMax > calcMaxLowering(p) + 1e-9) {
    ps.capNote = "lowering capped at " + formatNumber(ps.loweringCap) + " m (study asks " +
                 formatNumber(study.loweringMax) + " m): below that the shank COM would leave the shank or less than " +
                 formatNumber(p.minShankLength) + " m of shank would remain";
  }
  return ps;
}

// Adds participant i's points at each lowering, with and without each added mass that fits on
// the shortened shank, and a job for each to `work`.
void addSweepPoints(const SweepStudy& study, const Participant& p, std::size_t i, ParticipantSweep& ps,
                    std::vector<Job>& work) {
  for (double d : sweepLowerings(study, p)) {
    SweepPoint pt;
    pt.lowering = d;
    pt.onGrid =
        d <= study.loweringMax + 1e-9 && std::fabs(d / study.loweringStep - std::round(d / study.loweringStep)) < 1e-6;
    ps.points.push_back(pt);
    work.push_back({i, false, ps.points.size() - 1});
    for (double m : study.addedMasses) {
      if (m <= 0) continue;
      for (double at : study.addedMassDistances) {
        if (at > p.shank.length - d) continue;  // the mass must sit on the shortened shank
        SweepPoint mp;
        mp.lowering = d;
        mp.onGrid = pt.onGrid;
        mp.added = {m, at};
        ps.massPoints.push_back(mp);
        work.push_back({i, true, ps.massPoints.size() - 1});
      }
    }
  }
}

// Simulates one point's swing (with its trajectory unless it carries an added mass); a
// failure is the point's, never the end of the whole sweep.
void runSweepPoint(const SweepStudy& study, const Participant& p, const std::shared_ptr<const KneeLawSum>& knee,
                   SweepPoint& pt, bool withMass) {
  SwingSetup setup = makeSwingSetup(p, knee, pt.lowering, pt.added);
  setup.participant.kneeModelPath = studyKneeModelPath(study, p);  // the file actually used, for messages
  SwingOptions options = study.swing;
  options.recordTrajectory = !withMass;
  try {
    pt.result = simulateSwing(setup, options);
    pt.ok = true;
  } catch (const RunError& e) {
    pt.failure = e.what();
  } catch (const std::exception& e) {
    // Anything else (Simbody's own exceptions, a bad_alloc) is this point's failure with
    // the participant and lowering that caused it, never the end of the whole sweep.
    char where[96];
    std::snprintf(where, sizeof where, " at lowering %.4g m", pt.lowering);
    pt.failure = p.name + where + ": the simulation failed: " + e.what();
  }
  pt.ran = true;
}

// The index of the fastest ended swing on the grid (-1: none), marking points an interrupted
// sweep did not run.
int pickBest(std::vector<SweepPoint>& pts) {
  int best = -1;
  for (std::size_t k = 0; k < pts.size(); ++k) {
    if (!pts[k].ran) pts[k].failure = "not run (interrupted)";
    if (pts[k].ok && pts[k].onGrid &&
        (best < 0 || pts[k].result.swingTime < pts[static_cast<std::size_t>(best)].result.swingTime - 1e-12))
      best = static_cast<int>(k);
  }
  return best;
}

// The symmetry lowering over the points `best` is chosen from (on the grid, swing ended) and
// the two sides of each jump, each on its piece.
SymmetryLowering calcGridSymmetry(const ParticipantSweep& ps, const Participant& p) {
  std::vector<std::pair<double, double>> samples;  // (lowering m, swing time s)
  for (const SweepPoint& pt : ps.points)
    if (pt.onGrid)
      samples.emplace_back(pt.lowering, pt.ok ? pt.result.swingTime : std::numeric_limits<double>::quiet_NaN());
  for (const SwingTimeJump& j : ps.jumps) {
    samples.emplace_back(j.below.lowering, j.below.swingTime);
    samples.emplace_back(j.above.lowering, j.above.swingTime);
  }
  std::sort(samples.begin(), samples.end());
  std::vector<double> lowerings, swingTimes;
  std::vector<int> pieces;
  for (const auto& [lowering, time] : samples) {
    lowerings.push_back(lowering);
    swingTimes.push_back(time);
    pieces.push_back(calcPieceIndex(ps.jumps, lowering));
  }
  return calcSymmetryLowering(lowerings, swingTimes, p.soundLimbSwingTime.value_or(0), pieces);
}

// The jumps between neighbouring grid lowerings of one participant's plain sweep, each
// bisected with swings of the same set-up (no trajectory).
std::vector<SwingTimeJump> findGridJumps(const SweepStudy& study, const Participant& p,
                                         const std::shared_ptr<const KneeLawSum>& knee, const ParticipantSweep& ps) {
  std::vector<PieceSample> grid;
  for (const SweepPoint& pt : ps.points)
    if (pt.onGrid && pt.ok) grid.push_back(makePieceSample(pt.lowering, pt.result));
  const PieceSampler sample = [&](double lowering) -> std::optional<PieceSample> {
    SweepPoint pt;
    pt.lowering = lowering;
    runSweepPoint(study, p, knee, pt, true);
    if (!pt.ok) return std::nullopt;
    return makePieceSample(lowering, pt.result);
  };
  return findSwingTimeJumps(grid, sample, p.swingEnd.zoneOfStability);
}

}  // namespace

SweepResults runSweep(const SweepStudy& study, int jobs, const std::function<void(int, int)>& progress,
                      const volatile bool* stopFlag) {
  SweepResults results;
  results.study = study.name;
  std::vector<std::shared_ptr<const KneeLawSum>> knees;
  std::vector<Job> work;
  for (std::size_t i = 0; i < study.participants.size(); ++i) {
    const Participant& p = study.participants[i];
    knees.push_back(std::make_shared<const KneeLawSum>(makeKneeLaw(p, findStudyKneeModel(study, p))));
    ParticipantSweep ps = makeParticipantSweep(study, p);
    addSweepPoints(study, p, i, ps, work);
    results.participants.push_back(std::move(ps));
  }

  const int total = static_cast<int>(work.size());
  auto runOne = [&](const Job& job) {
    ParticipantSweep& ps = results.participants[job.participant];
    SweepPoint& pt = job.withMass ? ps.massPoints[job.index] : ps.points[job.index];
    runSweepPoint(study, study.participants[job.participant], knees[job.participant], pt, job.withMass);
  };
  runParallelJobs(
      total, jobs, [&](int k) { runOne(work[static_cast<std::size_t>(k)]); }, progress, stopFlag);

  // The jumps, one participant a job; not after an interrupt (the grid is incomplete).
  if (!(stopFlag && *stopFlag)) {
    runParallelJobs(static_cast<int>(results.participants.size()), jobs, [&](int i) {
      const auto k = static_cast<std::size_t>(i);
      results.participants[k].jumps = findGridJumps(study, study.participants[k], knees[k], results.participants[k]);
    });
  }
  for (std::size_t i = 0; i < results.participants.size(); ++i) {
    ParticipantSweep& ps = results.participants[i];
    ps.best = pickBest(ps.points);
    ps.bestWithMass = pickBest(ps.massPoints);
    ps.symmetry = calcGridSymmetry(ps, study.participants[i]);
  }
  return results;
}

}  // namespace swingsim
