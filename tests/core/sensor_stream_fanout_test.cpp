// The fan-out that feeds one sensor stream to several consumers on their own threads: every
// consumer reads every event in order, with images of its own; the producer waits for the
// slowest consumer (memory bound), not for one that left; a failed producer fails its consumers.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <future>
#include <thread>

#include "core/error.hpp"
#include "core/sensor_stream_fanout.hpp"

namespace wifislam {
namespace {

using namespace std::chrono_literals;

RgbdFrame frame_at(std::int64_t k) {
  RgbdFrame f;
  f.time = Timestamp::from_ns(1'000'000'000 * k);
  f.index = k;
  f.rgb = cv::Mat(4, 6, CV_8UC3, cv::Scalar::all(static_cast<double>(k % 200)));
  f.depth_m = cv::Mat(4, 6, CV_32FC1, cv::Scalar(0.5 * static_cast<double>(k)));
  return f;
}

OdometryReading odometry_at(std::int64_t k) {
  OdometryReading r;
  r.time = Timestamp::from_ns(1'000'000'000 * k - 500'000'000);
  r.base_in_odom.translation().x() = static_cast<double>(k);
  return r;
}

SensorStreamFacts facts() {
  SensorStreamFacts f;
  f.has_wifi = true;
  f.has_odometry = true;
  f.description = "test stream";
  f.camera_in_base.translation().z() = 0.7;
  return f;
}

TEST(SensorStreamFanout, EveryConsumerReadsEveryEventInOrderWithItsOwnImages) {
  SensorStreamFanout fanout(facts(), 3, /*window_frames=*/2);
  std::vector<std::future<std::vector<std::pair<int, std::int64_t>>>> readers;
  for (int i = 0; i < 3; ++i) {
    readers.push_back(std::async(std::launch::async, [&fanout, i] {
      SensorStream& s = fanout.consumer(i);
      EXPECT_TRUE(s.has_wifi());
      EXPECT_EQ(s.description(), "test stream");
      EXPECT_DOUBLE_EQ(s.camera_in_base().translation().z(), 0.7);
      // The first consumer scribbles over every image it gets: the others must not see it.
      std::vector<std::pair<int, std::int64_t>> out;
      while (std::optional<SensorEvent> e = s.next()) {
        if (auto* f = std::get_if<RgbdFrame>(&*e)) {
          EXPECT_EQ(f->rgb.at<cv::Vec3b>(1, 1)[0], f->index % 200);
          EXPECT_FLOAT_EQ(f->depth_m.at<float>(2, 2), 0.5f * static_cast<float>(f->index));
          if (i == 0) {
            f->rgb.setTo(cv::Scalar::all(255));
            f->depth_m.setTo(-1.0);
          }
        }
        out.emplace_back(static_cast<int>(e->index()), event_time(*e).ns);
      }
      return out;
    }));
  }
  std::vector<std::pair<int, std::int64_t>> expected;
  for (std::int64_t k = 1; k <= 40; ++k) {
    fanout.push(odometry_at(k));
    fanout.push(frame_at(k));
    expected.emplace_back(2, odometry_at(k).time.ns);
    expected.emplace_back(0, frame_at(k).time.ns);
  }
  fanout.close();
  for (auto& r : readers) EXPECT_EQ(r.get(), expected);
}

TEST(SensorStreamFanout, TheProducerWaitsForTheSlowestConsumerButNotForOneThatLeft) {
  SensorStreamFanout fanout(facts(), 2, /*window_frames=*/3);
  for (std::int64_t k = 0; k < 3; ++k) fanout.push(frame_at(k));  // the window is full now
  std::atomic<bool> pushed{false};
  std::thread producer([&] {
    fanout.push(frame_at(3));
    pushed = true;
  });
  // The producer's own count of the times it found the window full, not a sleep: once it has
  // looked and waited, and again after consumer 0's read woke it, the frame is still out.
  while (fanout.producer_waits() < 1) std::this_thread::yield();
  EXPECT_FALSE(pushed) << "a fourth frame went in while no consumer had read any";
  ASSERT_TRUE(fanout.consumer(0).next().has_value());
  while (fanout.producer_waits() < 2) std::this_thread::yield();
  EXPECT_FALSE(pushed) << "consumer 1 still has the first frame to read";
  ASSERT_TRUE(fanout.consumer(1).next().has_value());
  producer.join();  // both read frame 0: room for frame 3
  EXPECT_TRUE(pushed);

  fanout.leave(1);  // consumer 1 stops: only consumer 0 holds the producer back now
  std::thread more([&] {
    for (std::int64_t k = 4; k < 20; ++k) fanout.push(frame_at(k));
    fanout.close();
  });
  std::int64_t last = -1;
  while (std::optional<SensorEvent> e = fanout.consumer(0).next())
    last = std::get<RgbdFrame>(*e).index;
  more.join();
  EXPECT_EQ(last, 19);
}

TEST(SensorStreamFanout, AFailedProducerFailsItsConsumersAndLeftConsumersDropEvents) {
  SensorStreamFanout fanout(facts(), 1, 2);
  fanout.push(frame_at(0));
  fanout.abort("disk full");
  try {
    (void)fanout.consumer(0).next();
    FAIL() << "next() returned after the producer failed";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("disk full"), std::string::npos) << e.what();
  }

  SensorStreamFanout nobody(facts(), 1, 1);
  nobody.leave(0);
  for (std::int64_t k = 0; k < 10; ++k) nobody.push(frame_at(k));  // would block if kept
  nobody.close();
}

/// A source of `frames` frames that counts how many it was asked for.
class CountingStream : public SensorStream {
 public:
  explicit CountingStream(std::int64_t frames) : frames_(frames) {}
  std::optional<SensorEvent> next() override {
    if (served_ == frames_) return std::nullopt;
    return frame_at(served_++);
  }
  const CameraIntrinsics& intrinsics() const override { return intrinsics_; }
  bool has_wifi() const override { return false; }
  bool has_odometry() const override { return false; }
  std::string description() const override { return "counting"; }
  std::int64_t served() const { return served_; }

 private:
  std::int64_t frames_, served_ = 0;
  CameraIntrinsics intrinsics_;
};

// Once every consumer has left (each run failed, or was stopped by Ctrl-C), pumping on rendered
// every remaining frame for no one: a stopped compare waited for a whole second rendering.
TEST(SensorStreamFanout, PumpStopsTakingFromItsSourceOnceEveryConsumerHasLeft) {
  SensorStreamFanout fanout(facts(), 2, 2);
  CountingStream source(1000);
  std::thread reader([&] {
    for (int k = 0; k < 5; ++k) ASSERT_TRUE(fanout.consumer(0).next().has_value());
    fanout.leave(0);
  });
  fanout.leave(1);
  fanout.pump(source);
  reader.join();
  EXPECT_LT(source.served(), 20) << "the source was drained for no reader";
  EXPECT_GE(source.served(), 5);

  // With a reader to the end, every event is pumped.
  SensorStreamFanout kept(facts(), 1, 2);
  CountingStream all(50);
  std::int64_t read = 0;
  std::thread whole([&] {
    while (kept.consumer(0).next()) ++read;
  });
  kept.pump(all);
  whole.join();
  EXPECT_EQ(all.served(), 50);
  EXPECT_EQ(read, 50);
}

}  // namespace
}  // namespace wifislam
