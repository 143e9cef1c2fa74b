#pragma once
// The reference frame of the determinism tests, rendered the same way in-process and by the
// render_frame_tool executable.

#include <cstdint>
#include <string>

namespace wifislam::test {

/// Renders the hand-built corridor from a fixed pose with the full sensor model and writes
/// <prefix>_rgb.png and <prefix>_depth.png.
void render_reference_frame(const std::string& prefix, std::uint64_t seed,
                            std::int64_t frame_index);

}  // namespace wifislam::test
