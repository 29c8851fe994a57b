#include "report/stick_figure_animation.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "core/text_format.h"

namespace swingsim {

namespace {

constexpr double kMargin = 0.08;  // m of space around the leg's reach

// The trajectory samples shown: the first, then the first at or after every frame step, up to
// the swing end, and the last at or before the swing end.
std::vector<std::size_t> chooseFrames(const SwingTrajectory& tr, double swingTime) {
  std::vector<std::size_t> frames = {0};
  double next = kStickFigureFrameStep;
  for (std::size_t k = 1; k < tr.size() && tr.time[k] <= swingTime + 1e-9; ++k) {
    if (tr.time[k] + 1e-9 >= next) {
      frames.push_back(k);
      next = tr.time[k] + kStickFigureFrameStep;
    }
  }
  std::size_t last = frames.back();
  while (last + 1 < tr.size() && tr.time[last + 1] <= swingTime + 1e-9) ++last;
  if (last != frames.back()) frames.push_back(last);
  return frames;
}

// The visible box, m: everything the leg reaches during the shown frames.
struct Box {
  double xLo, xHi, yLo, yHi;
};

Box calcBox(const SwingTrajectory& tr, const std::vector<std::size_t>& frames, double hipHeight) {
  Box b{0, 0, 0, hipHeight};
  for (std::size_t k : frames) {
    for (double x : {tr.kneeX[k], tr.ankleX[k], tr.toeX[k]}) b.xLo = std::min(b.xLo, x), b.xHi = std::max(b.xHi, x);
    for (double y : {tr.kneeY[k], tr.ankleY[k], tr.toeY[k]}) b.yLo = std::min(b.yLo, y), b.yHi = std::max(b.yHi, y);
  }
  return {b.xLo - kMargin, b.xHi + kMargin, b.yLo - kMargin, b.yHi + kMargin};
}

std::string px(double v) { return fmt("%.2f", v); }

}  // namespace

std::string renderStickFigureAnimation(const SwingResult& r, double hipHeight) {
  const SwingTrajectory& tr = r.trajectory;
  if (tr.size() == 0 || !(r.swingTime > 0))
    throw std::invalid_argument(
        "renderStickFigureAnimation: expected a swing with a trajectory and a positive swing "
        "time, found " +
        std::to_string(tr.size()) + " samples and " + fmt("%g", r.swingTime) + " s");
  const std::vector<std::size_t> frames = chooseFrames(tr, r.swingTime);
  const Box box = calcBox(tr, frames, hipHeight);
  auto sx = [&](double x) { return (x - box.xLo) * kStickFigurePxPerMetre; };
  auto sy = [&](double y) { return (box.yHi - y) * kStickFigurePxPerMetre; };
  const double width = sx(box.xHi), height = sy(box.yLo);
  const double duration = tr.time[frames.back()] + kStickFigureHold;

  std::string keyTimes;
  for (std::size_t k : frames) keyTimes += fmt("%.4f", tr.time[k] / duration) + ";";
  keyTimes += "1";
  // One <animate> per endpoint coordinate (the hip's too, which stays put): the frames' values, then the last held to
  // the end.
  auto animate = [&](const char* attribute, const std::vector<double>& column, bool isX) {
    std::string values;
    for (std::size_t k : frames) values += px(isX ? sx(column[k]) : sy(column[k])) + ";";
    const double last = column[frames.back()];
    values += px(isX ? sx(last) : sy(last));
    return std::string("<animate attributeName=\"") + attribute + "\" dur=\"" + fmt("%.4f", duration) +
           "s\" repeatCount=\"indefinite\" calcMode=\"linear\" keyTimes=\"" + keyTimes + "\" values=\"" + values +
           "\"/>";
  };
  const std::vector<double> hipX(tr.size(), 0.0), hipY(tr.size(), hipHeight);
  struct Segment {
    const char* name;
    const char* colour;
    const std::vector<double>&x1, &y1, &x2, &y2;
  };
  const Segment segments[] = {{"thigh", "#0072B2", hipX, hipY, tr.kneeX, tr.kneeY},
                              {"shank", "#D55E00", tr.kneeX, tr.kneeY, tr.ankleX, tr.ankleY},
                              {"foot", "#009E73", tr.ankleX, tr.ankleY, tr.toeX, tr.toeY}};

  std::string s = "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"stick-figure\" width=\"" + px(width) +
                  "\" height=\"" + px(height) + "\" viewBox=\"0 0 " + px(width) + " " + px(height) + "\">\n";
  s += "<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n";
  s += "<line x1=\"0\" y1=\"" + px(sy(0)) + "\" x2=\"" + px(width) + "\" y2=\"" + px(sy(0)) +
       "\" stroke=\"#555555\" stroke-dasharray=\"6 4\"/>\n";
  std::string toePath;
  for (std::size_t k : frames) toePath += px(sx(tr.toeX[k])) + "," + px(sy(tr.toeY[k])) + " ";
  s += "<polyline points=\"" + toePath + "\" fill=\"none\" stroke=\"#bbbbbb\" stroke-width=\"1.5\"/>\n";
  const std::size_t first = frames.front();
  for (const Segment& seg : segments) {
    s += std::string("<line class=\"") + seg.name + "\" x1=\"" + px(sx(seg.x1[first])) + "\" y1=\"" +
         px(sy(seg.y1[first])) + "\" x2=\"" + px(sx(seg.x2[first])) + "\" y2=\"" + px(sy(seg.y2[first])) +
         "\" stroke=\"" + seg.colour + "\" stroke-width=\"6\" stroke-linecap=\"round\">";
    s += animate("x1", seg.x1, true) + animate("y1", seg.y1, false) + animate("x2", seg.x2, true) +
         animate("y2", seg.y2, false);
    s += "</line>\n";
  }
  s += "<circle cx=\"" + px(sx(0)) + "\" cy=\"" + px(sy(hipHeight)) + "\" r=\"6\" fill=\"#111111\"/>\n";
  return s + "</svg>\n";
}

}  // namespace swingsim
