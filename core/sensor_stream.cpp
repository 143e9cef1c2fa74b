#include "core/sensor_stream.hpp"

namespace wifislam {

Timestamp event_time(const SensorEvent& event) {
  return std::visit([](const auto& e) { return e.time; }, event);
}

}  // namespace wifislam
