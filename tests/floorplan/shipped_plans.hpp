#pragma once
// The real floor plans the repository ships (assets/floorplans, each with its licence), which the
// import tests read.

#include <filesystem>

namespace wifislam::test {

inline const std::filesystem::path kShippedPlans =
    std::filesystem::path(WIFISLAM_SCENES_DIR).parent_path() / "assets" / "floorplans";

}  // namespace wifislam::test
