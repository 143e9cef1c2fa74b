// libFuzzer driver for the `study` target (fuzz/fuzz_targets.hpp); scripts/fuzz.sh runs it.
#include "fuzz/fuzz_targets.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  wifislam::fuzz::run_study(data, size);
  return 0;
}
