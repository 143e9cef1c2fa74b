// Renders one frame of the hand-built corridor and writes <prefix>_rgb.png and <prefix>_depth.png:
// the determinism test runs it in separate processes and compares the bytes.
//   render_frame_tool <prefix> <seed> <frame_index>

#include <cstdio>
#include <cstdlib>
#include <string>

#include "tests/sim/render/render_frame_tool.hpp"

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: %s <prefix> <seed> <frame_index>\n", argv[0]);
    return 2;
  }
  wifislam::test::render_reference_frame(argv[1], std::stoull(argv[2]), std::stoll(argv[3]));
  return 0;
}
