#include "sweep/burkett_published.h"

namespace swingsim {

const std::vector<PublishedParticipant>& publishedParticipants() {
  // Burkett 2004 Table 3 and Table 4.
  static const std::vector<PublishedParticipant> rows = {
      {"P1",
       0.420,
       0.463,
       0.031,
       0.100,
       {{0.000, 0.463, 0.420, 0.499},
        {0.050, 0.423, 0.405, 0.462},
        {0.100, 0.410, 0.375, 0.419},
        {0.150, 0.418, 0.465, 0.452}}},
      {"P2",
       0.495,
       0.385,
       0.047,
       0.125,
       {{0.000, 0.385, 0.495, 0.332},
        {0.080, 0.361, 0.465, 0.313},
        {0.125, 0.314, 0.450, 0.336},
        {0.180, 0.280, 0.480, 0.303}}},
      {"P3",
       0.420,
       0.496,
       0.046,
       0.200,
       {{0.000, 0.496, 0.420, 0.478},
        {0.140, 0.502, 0.405, 0.450},
        {0.200, 0.428, 0.380, 0.441},
        {0.240, 0.383, 0.440, 0.478}}},
      {"P4",
       0.450,
       0.444,
       0.033,
       0.175,
       {{0.000, 0.444, 0.450, 0.396},
        {0.090, 0.417, 0.435, 0.390},
        {0.130, 0.411, 0.435, 0.403},
        {0.175, 0.349, 0.420, 0.381}}},
  };
  return rows;
}

const PublishedParticipant* findPublished(const std::string& name) {
  for (const auto& p : publishedParticipants()) {
    if (p.name == name) return &p;
  }
  return nullptr;
}

}  // namespace swingsim
