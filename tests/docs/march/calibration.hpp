#include <proceduray/march/calibration.hpp>
// What the usage block assumes: a scene's uniform with a knob per object id.
struct DocConstants {
  proceduray::MarchKnobs knobs[4];
};
inline constexpr int cog_id = 3;
// @declarations
void usage(DocConstants& constants) {
  // @statements
}
