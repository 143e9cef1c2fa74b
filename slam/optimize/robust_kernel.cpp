#include "slam/optimize/robust_kernel.hpp"

#include "core/error.hpp"

namespace wifislam::slam {

std::string to_string(RobustKernel::Kind kind) {
  switch (kind) {
    case RobustKernel::Kind::kNone:
      return "none";
    case RobustKernel::Kind::kHuber:
      return "huber";
    case RobustKernel::Kind::kCauchy:
      return "cauchy";
  }
  return "none";
}

RobustKernel::Kind robust_kernel_kind(const std::string& name) {
  for (RobustKernel::Kind kind :
       {RobustKernel::Kind::kNone, RobustKernel::Kind::kHuber, RobustKernel::Kind::kCauchy}) {
    if (to_string(kind) == name) return kind;
  }
  throw InvalidInputError("robust kernel must be none, huber or cauchy, got '" + name + "'");
}

}  // namespace wifislam::slam
