#pragma once
// The two choices a scene makes of its mean path loss: which model computes it
// (propagation_model.hpp says what each computes), and which of ITU-R P.1238's environments its
// tables are read for.

namespace wifislam::radio_model {

enum class PathLossModel { kItuWalls, kItuSiteGeneral, kItuSiteGeneralFit };
const char* to_string(PathLossModel model);

enum class RadioEnvironment { kResidential, kOffice, kCommercial };
const char* to_string(RadioEnvironment environment);

}  // namespace wifislam::radio_model
