#pragma once
// One sensor stream read by several consumers at once: a producer pushes the events (time
// order, as SensorStream promises) and each consumer reads all of them through its own
// SensorStream, on its own thread. This is how one rendering feeds the vanilla and Wi-Fi runs of
// a study case side by side, with no PNG round trip between them.
//
// Memory stays flat whatever the route's length: the producer waits while the slowest consumer
// still has `window_frames` frames to read (odometry and scans between frames do not count; they
// are small). Each consumer gets its own deep copy of every frame's images, so a consumer that
// wrote into them could not change what another reads: the runs stay independent and
// deterministic.
//
// Failures: a consumer that stops early (its run failed) calls leave() and is no longer waited
// for; a producer that fails calls abort(), and every consumer's next() then throws.

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "core/sensor_stream.hpp"

namespace wifislam {

/// What a SensorStream says about itself besides its events.
struct SensorStreamFacts {
  CameraIntrinsics intrinsics;
  Pose camera_in_base = Pose::Identity();
  bool has_wifi = false;
  bool has_odometry = false;
  std::string description;

  static SensorStreamFacts of(const SensorStream& stream);
};

class SensorStreamFanout {
 public:
  SensorStreamFanout(SensorStreamFacts facts, int consumers, int window_frames = 8);
  ~SensorStreamFanout();
  SensorStreamFanout(const SensorStreamFanout&) = delete;
  SensorStreamFanout& operator=(const SensorStreamFanout&) = delete;

  int consumers() const { return static_cast<int>(branches_.size()); }
  /// Consumer i's stream (0 <= i < consumers()); read it from one thread only.
  SensorStream& consumer(int i);

  /// Producer: appends an event, waiting while a consumer that has not left is window_frames
  /// frames behind. Once every consumer has left, events are dropped.
  void push(SensorEvent event);
  /// Producer: no more events; consumers' next() returns nullopt after the last one.
  void close();
  /// Producer: it failed; consumers' next() throws Error naming `why`.
  void abort(const std::string& why);
  /// Pushes every event of `source`, then closes (abort() and rethrow if the source throws).
  /// Stops early once every consumer has left (each failed, or was stopped by Ctrl-C): the rest
  /// of the source would be made for no one (a rendering: seconds to minutes).
  void pump(SensorStream& source);

  /// Consumer i reads no more (it failed or finished early): the producer stops waiting for it.
  void leave(int i);

  /// How many times push() has found the window full and waited (once per look: a woken producer
  /// that is still held back counts again). Lets a test see the producer blocked without sleeping.
  std::int64_t producer_waits() const;

 private:
  class Branch;
  friend class Branch;

  std::optional<SensorEvent> next_for(int i);
  /// Drops the events every remaining consumer has read. Caller holds mutex_.
  void trim();

  const SensorStreamFacts facts_;
  const int window_frames_;
  std::vector<std::unique_ptr<Branch>> branches_;

  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<std::shared_ptr<const SensorEvent>> events_;
  std::int64_t first_sequence_ = 0;  // sequence number of events_.front()
  std::vector<std::int64_t> next_;   // per consumer: sequence number of its next event
  std::vector<bool> reading_;        // per consumer: has not left
  int frames_held_ = 0;              // frames among events_
  std::int64_t producer_waits_ = 0;
  bool closed_ = false;
  std::string aborted_;  // non-empty: why the producer failed
};

}  // namespace wifislam
