#include "sim/site/survey_site.hpp"

#include "sim/site/radio_options.hpp"
#include "sim/world/plan_queries.hpp"
#include "sim/world/radio_wall_mesh.hpp"
#include "sim/world/world_types.hpp"

namespace wifislam::sim::site {

radio_model::calibrate::SurveySite survey_site(const Site& site) {
  const scene::Scene& scene = site.scene();
  const world::FloorPlan& plan = site.world().plan;
  radio_model::calibrate::SurveySite out;
  out.name = scene.name;
  out.access_points_where = scene.where("access_points");
  out.walls = world::radio_wall_mesh(site.world().mesh);
  out.bounds_min_m = plan.bounds_min_m;
  out.bounds_max_m = plan.bounds_max_m;
  out.ceiling_m = scene.building.wall_height_m;
  out.in_free_space = [&plan](const Eigen::Vector2d& p) {
    return world::regions_contain(plan.free_space, p);
  };
  out.options = propagation_options(scene);
  out.seed = scene.seed;
  return out;
}

}  // namespace wifislam::sim::site
