#include "radio_model/path_loss_choice.hpp"

namespace wifislam::radio_model {

const char* to_string(PathLossModel model) {
  switch (model) {
    case PathLossModel::kItuWalls:
      return "itu_walls";
    case PathLossModel::kItuSiteGeneral:
      return "itu_site_general";
    case PathLossModel::kItuSiteGeneralFit:
      return "itu_site_general_fit";
  }
  return "unknown";
}

const char* to_string(RadioEnvironment environment) {
  switch (environment) {
    case RadioEnvironment::kResidential:
      return "residential";
    case RadioEnvironment::kOffice:
      return "office";
    case RadioEnvironment::kCommercial:
      return "commercial";
  }
  return "unknown";
}

}  // namespace wifislam::radio_model
