// Opens a model written by `swingsim export-osim` with OpenSim itself and reports what OpenSim
// sees: coordinates (names, ranges, defaults), bodies and masses, attached geometry; then plays
// a motion (.sto or .mot: simulate's trajectory or a lab's IK file) on it, frame by frame, and
// reports which columns named a coordinate and the range each coordinate and the toe frame went
// through. Built against OpenSim by scripts/opensim/build-opensim.sh; not part of swingsim's
// build or CI (docs/opensim-check.md).
#include <OpenSim/Common/Storage.h>
#include <OpenSim/Simulation/Model/Model.h>

#include <algorithm>
#include <cstdio>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace {

void printModel(OpenSim::Model& model, const SimTK::State& state) {
    std::printf("model %s: %d bodies, %d coordinates, total mass %.4f kg\n",
                model.getName().c_str(), model.getBodySet().getSize(),
                model.getCoordinateSet().getSize(), model.getTotalMass(state));
    for (const auto& body : model.getComponentList<OpenSim::Body>())
        std::printf("  body %-14s mass %8.4f kg\n", body.getName().c_str(), body.getMass());
    for (const auto& shape : model.getComponentList<OpenSim::Geometry>()) {
        if (shape.getConcreteClassName() == "FrameGeometry") continue;  // every frame's axes
        std::printf("  geometry %-24s %-10s on frame %s\n", shape.getName().c_str(),
                    shape.getConcreteClassName().c_str(), shape.getFrame().getName().c_str());
    }
    for (const auto& c : model.getComponentList<OpenSim::Coordinate>()) {
        std::printf("  coordinate %-16s range [%8.2f, %8.2f] deg, default %7.2f deg\n",
                    c.getName().c_str(), SimTK::convertRadiansToDegrees(c.getRangeMin()),
                    SimTK::convertRadiansToDegrees(c.getRangeMax()),
                    SimTK::convertRadiansToDegrees(c.getDefaultValue()));
    }
    const SimTK::Vec3 com = model.calcMassCenterPosition(state);
    std::printf("  whole-model centre of mass at default pose (%.4f, %.4f, %.4f) m\n", com[0],
                com[1], com[2]);
}

// The body whose name starts with `prefix` (the last such), else the last body.
const OpenSim::Body& bodyNamed(const OpenSim::Model& model, const std::string& prefix) {
    const OpenSim::BodySet& bodies = model.getBodySet();
    for (int i = bodies.getSize() - 1; i >= 0; --i)
        if (bodies[i].getName().rfind(prefix, 0) == 0) return bodies[i];
    return bodies[bodies.getSize() - 1];
}

// Plays `path` on the model; over the frames with time in [from, to] the lowest height in
// ground of the ankle (talus origin) and the toe (toes origin) is reported, as swingsim's
// "min toe clearance" takes the lower of the two from peak knee flexion to the swing end.
int playMotion(OpenSim::Model& model, SimTK::State& state, const std::string& path, double from,
               double to) {
    OpenSim::Storage motion(path);
    const OpenSim::Array<std::string>& labels = motion.getColumnLabels();
    std::map<std::string, std::vector<double>> columns;  // coordinate name -> values, rad or m
    for (int i = 1; i < labels.getSize(); ++i) {
        const std::string& label = labels[i];
        if (!model.getCoordinateSet().contains(label)) {
            std::printf("  column %-24s names no coordinate of the model\n", label.c_str());
            continue;
        }
        OpenSim::Array<double> values;
        motion.getDataColumn(label, values);
        const OpenSim::Coordinate& c = model.getCoordinateSet().get(label);
        const bool angle = c.getMotionType() == OpenSim::Coordinate::Rotational;
        std::vector<double>& v = columns[label];
        for (int k = 0; k < values.getSize(); ++k)
            v.push_back(angle && motion.isInDegrees() ? SimTK::convertDegreesToRadians(values[k])
                                                      : values[k]);
        std::printf("  column %-24s -> coordinate %s\n", label.c_str(), label.c_str());
    }
    if (columns.empty()) {
        std::printf("no column of %s names a coordinate: nothing to play\n", path.c_str());
        return 1;
    }
    const OpenSim::Body& toe = bodyNamed(model, "toes");
    const OpenSim::Body& ankle = bodyNamed(model, "talus");
    double toeMin = std::numeric_limits<double>::infinity(), toeMax = -toeMin;
    double windowMin = toeMin;
    const int frames = motion.getSize();
    for (int k = 0; k < frames; ++k) {
        for (auto& [name, v] : columns) model.getCoordinateSet().get(name).setValue(state, v[k], false);
        model.realizePosition(state);
        const double y = toe.getPositionInGround(state)[1];
        toeMin = std::min(toeMin, y);
        toeMax = std::max(toeMax, y);
        double t = 0;
        motion.getTime(k, t);
        if (t >= from && t <= to)
            windowMin = std::min({windowMin, y, ankle.getPositionInGround(state)[1]});
    }
    std::printf("played %d frames of %s\n", frames, path.c_str());
    for (auto& [name, v] : columns) {
        const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
        std::printf("  %-16s from %8.2f to %8.2f deg\n", name.c_str(),
                    SimTK::convertRadiansToDegrees(*lo), SimTK::convertRadiansToDegrees(*hi));
    }
    std::printf("  %s origin height in ground from %.4f to %.4f m\n", toe.getName().c_str(),
                toeMin, toeMax);
    if (from <= to)
        std::printf("  lowest of %s and %s origins from %.4f to %.4f s: %.6f m\n",
                    ankle.getName().c_str(), toe.getName().c_str(), from, to, windowMin);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr,
                     "usage: check_exported_model MODEL.osim [MOTION.sto|.mot ...] "
                     "[--window FROM_S TO_S]\n");
        return 2;
    }
    try {
        OpenSim::Model model(argv[1]);
        SimTK::State& state = model.initSystem();
        printModel(model, state);
        std::vector<std::string> motions(argv + 2, argv + argc);
        double from = 1, to = 0;  // no window
        if (motions.size() >= 3 && motions[motions.size() - 3] == "--window") {
            from = std::stod(motions[motions.size() - 2]);
            to = std::stod(motions.back());
            motions.resize(motions.size() - 3);
        }
        int rc = 0;
        for (const std::string& m : motions) rc |= playMotion(model, state, m, from, to);
        return rc;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "OpenSim refused: %s\n", e.what());
        return 1;
    }
}
