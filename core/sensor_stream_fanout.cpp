#include "core/sensor_stream_fanout.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "core/error.hpp"

namespace wifislam {

SensorStreamFacts SensorStreamFacts::of(const SensorStream& stream) {
  return {stream.intrinsics(), stream.camera_in_base(), stream.has_wifi(), stream.has_odometry(),
          stream.description()};
}

/// One consumer's view: the fan-out's facts and its own position in the events.
class SensorStreamFanout::Branch final : public SensorStream {
 public:
  Branch(SensorStreamFanout& fanout, int index) : fanout_(fanout), index_(index) {}
  std::optional<SensorEvent> next() override { return fanout_.next_for(index_); }
  const CameraIntrinsics& intrinsics() const override { return fanout_.facts_.intrinsics; }
  Pose camera_in_base() const override { return fanout_.facts_.camera_in_base; }
  bool has_wifi() const override { return fanout_.facts_.has_wifi; }
  bool has_odometry() const override { return fanout_.facts_.has_odometry; }
  std::string description() const override { return fanout_.facts_.description; }

 private:
  SensorStreamFanout& fanout_;
  int index_;
};

SensorStreamFanout::SensorStreamFanout(SensorStreamFacts facts, int consumers, int window_frames)
    : facts_(std::move(facts)),
      window_frames_(std::max(1, window_frames)),
      next_(static_cast<std::size_t>(std::max(0, consumers)), 0),
      reading_(static_cast<std::size_t>(std::max(0, consumers)), true) {
  for (int i = 0; i < consumers; ++i) branches_.push_back(std::make_unique<Branch>(*this, i));
}

SensorStreamFanout::~SensorStreamFanout() = default;

SensorStream& SensorStreamFanout::consumer(int i) {
  return *branches_.at(static_cast<std::size_t>(i));
}

void SensorStreamFanout::push(SensorEvent event) {
  const bool frame = std::holds_alternative<RgbdFrame>(event);
  std::unique_lock lock(mutex_);
  const auto anyone_reading = [&] {
    return std::find(reading_.begin(), reading_.end(), true) != reading_.end();
  };
  changed_.wait(lock, [&] {
    const bool room = !frame || frames_held_ < window_frames_ || !anyone_reading();
    producer_waits_ += !room;
    return room;
  });
  if (!anyone_reading()) return;
  events_.push_back(std::make_shared<const SensorEvent>(std::move(event)));
  frames_held_ += frame;
  changed_.notify_all();
}

std::int64_t SensorStreamFanout::producer_waits() const {
  std::lock_guard lock(mutex_);
  return producer_waits_;
}

void SensorStreamFanout::close() {
  std::lock_guard lock(mutex_);
  closed_ = true;
  changed_.notify_all();
}

void SensorStreamFanout::abort(const std::string& why) {
  std::lock_guard lock(mutex_);
  aborted_ = why.empty() ? "unknown error" : why;
  changed_.notify_all();
}

void SensorStreamFanout::pump(SensorStream& source) {
  try {
    while (std::optional<SensorEvent> event = source.next()) {
      push(std::move(*event));
      std::lock_guard lock(mutex_);
      if (std::find(reading_.begin(), reading_.end(), true) == reading_.end()) break;
    }
  } catch (const std::exception& e) {
    abort(e.what());
    throw;
  }
  close();
}

void SensorStreamFanout::leave(int i) {
  std::lock_guard lock(mutex_);
  reading_.at(static_cast<std::size_t>(i)) = false;
  trim();
  changed_.notify_all();
}

std::optional<SensorEvent> SensorStreamFanout::next_for(int i) {
  const auto at = static_cast<std::size_t>(i);
  std::shared_ptr<const SensorEvent> event;
  {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [&] {
      return !aborted_.empty() || closed_ ||
             next_[at] < first_sequence_ + static_cast<std::int64_t>(events_.size());
    });
    if (!aborted_.empty()) {
      throw Error(fmt::format("the stream '{}' failed: {}", facts_.description, aborted_));
    }
    if (next_[at] == first_sequence_ + static_cast<std::int64_t>(events_.size())) {
      return std::nullopt;  // closed, and this consumer has read everything
    }
    event = events_[static_cast<std::size_t>(next_[at] - first_sequence_)];
    ++next_[at];
    trim();
  }
  changed_.notify_all();
  // The copy (images deep-copied) is made outside the lock: consumers do not wait on each other.
  SensorEvent copy = *event;
  if (auto* frame = std::get_if<RgbdFrame>(&copy)) {
    frame->rgb = frame->rgb.clone();
    frame->depth_m = frame->depth_m.clone();
  }
  return copy;
}

void SensorStreamFanout::trim() {
  std::int64_t oldest_unread = first_sequence_ + static_cast<std::int64_t>(events_.size());
  for (std::size_t c = 0; c < next_.size(); ++c)
    if (reading_[c]) oldest_unread = std::min(oldest_unread, next_[c]);
  while (first_sequence_ < oldest_unread) {
    frames_held_ -= std::holds_alternative<RgbdFrame>(*events_.front());
    events_.pop_front();
    ++first_sequence_;
  }
}

}  // namespace wifislam
