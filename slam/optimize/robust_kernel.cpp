#include "slam/optimize/robust_kernel.hpp"

#include "core/error.hpp"

namespace wifislam::slam::optimize {

const options::Choices<RobustKernel::Kind>& robust_kernel_kinds() {
  static const options::Choices<RobustKernel::Kind> kinds = {
      {RobustKernel::Kind::kNone, "none"},
      {RobustKernel::Kind::kHuber, "huber"},
      {RobustKernel::Kind::kCauchy, "cauchy"}};
  return kinds;
}

std::string to_string(RobustKernel::Kind kind) {
  for (const auto& [value, name] : robust_kernel_kinds()) {
    if (value == kind) return std::string(name);
  }
  return "none";
}

}  // namespace wifislam::slam::optimize
