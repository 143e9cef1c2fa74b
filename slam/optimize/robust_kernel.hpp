#pragma once
// The robust kernel of pose-graph edges: a loss that grows like chi^2 for consistent edges and
// more slowly beyond `width_chi2`, so one wrong edge cannot drag the whole graph. Widths are on
// the chi^2 scale of the edge's information (chi^2 = r^T Omega r, 6 degrees of freedom), the
// scale on which after-run pruning thresholds are stated too (edge_pruning.hpp).

#include <string>

#include "core/option_table.hpp"

namespace wifislam::slam::optimize {

struct RobustKernel {
  enum class Kind { kNone, kHuber, kCauchy };
  Kind kind = Kind::kNone;
  /// chi^2 at which the kernel leaves the quadratic (Huber: delta^2; Cauchy: its scale b).
  double width_chi2 = 9.0;
  /// On every edge (RGBDSLAMv2 sets one on each edge) or on loop-closure edges only.
  bool every_edge = false;
};

/// Each kind with its name ("none", "huber", "cauchy"): the one spelling of the names, for
/// options (`--set robust_kernel=`), run.json and messages.
const options::Choices<RobustKernel::Kind>& robust_kernel_kinds();
/// The kind's name.
std::string to_string(RobustKernel::Kind kind);

}  // namespace wifislam::slam::optimize
