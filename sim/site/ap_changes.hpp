#pragma once
// The building's access points in a later session: the scene's `access_points.changes` applied,
// in list order, for every change of a session up to the scene's own (Scene::session). Session 0
// (or a scene without changes) is the building as placed.
//
//   off     the AP no longer transmits: it is not in the session's radio model at all.
//   moved   the AP (same BSSIDs and channels) stands at `position_m`. Its shadowing field stays
//           the one drawn for its id: moving changes its distances and the walls its links cross,
//           not the shadowing draw (a simplification; a new AP gets a field of its own).
//   power   its tx power steps by `tx_power_step_db` (clamped to a Wi-Fi radio's range).
//   new     an AP is installed at `position_m`; its id follows every AP the placement made and
//           every new AP listed before it, whatever the session, so a new AP has one id (and one
//           set of BSSIDs) in every session it exists in.
//
// A change naming an AP that does not exist (or was switched off by an earlier change) is
// rejected at its key (Scene::reject), as is a position outside the building.

#include <vector>

#include "radio_model/access_point.hpp"
#include "sim/scene/scene.hpp"
#include "sim/world/world_types.hpp"

namespace wifislam::sim::site {

/// `aps`, the building's APs as placed (ids 0..n-1), as they are in the scene's session.
std::vector<radio_model::AccessPoint> apply_access_point_changes(
    std::vector<radio_model::AccessPoint> aps, const scene::Scene& scene,
    const world::World& world);

}  // namespace wifislam::sim::site
