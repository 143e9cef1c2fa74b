#include "study/recorded_dataset.hpp"

#include <deque>
#include <future>
#include <stdexcept>

#include <fmt/format.h>

#include "core/worker_pool.hpp"
#include "sim/generate/dataset_writer.hpp"
#include "sim/generate/generator_stream.hpp"
#include "slam/io/run_folder_writer.hpp"
#include "slam/system/run_slam.hpp"

namespace wifislam::study {

class RecordedDataset::Replay final : public SensorStream {
 public:
  explicit Replay(const RecordedDataset& dataset) : dataset_(dataset) {}
  std::optional<SensorEvent> next() override {
    if (next_ >= dataset_.events_.size()) return std::nullopt;
    return dataset_.events_[next_++];
  }
  const CameraIntrinsics& intrinsics() const override { return dataset_.facts_.intrinsics; }
  Pose camera_in_base() const override { return dataset_.facts_.camera_in_base; }
  bool has_wifi() const override { return dataset_.facts_.has_wifi; }
  bool has_odometry() const override { return dataset_.facts_.has_odometry; }
  std::string description() const override { return dataset_.facts_.description; }

 private:
  const RecordedDataset& dataset_;
  std::size_t next_ = 0;
};

RecordedDataset::RecordedDataset(std::shared_ptr<const sim::site::Site> site,
                                 const std::filesystem::path& dataset_dir,
                                 sim::generate::GenerateOptions generate,
                                 std::vector<slam::feature::FeatureOptions> features, int threads)
    : dataset_dir_(dataset_dir),
      facts_(sim::generate::generated_stream_facts(
          *site, fmt::format("dataset {} (frames recorded as it was generated, features "
                             "extracted once)",
                             dataset_dir.filename().string()))) {
  if (generate.on_event) throw std::invalid_argument("RecordedDataset sets on_event itself");
  for (const slam::feature::FeatureOptions& options : features) {
    if (this->features(options) == nullptr) {
      stores_.push_back(std::make_unique<slam::feature::FeatureStore>(options, facts_.intrinsics));
    }
  }
  // Frames wait here for extraction; the generation waits once `window` frames are in flight,
  // so memory stays bounded whatever the route's length.
  WorkerPool pool(clamp_thread_count(threads));
  const std::size_t window = 4 * static_cast<std::size_t>(std::max(1, pool.size()));
  std::deque<std::future<void>> in_flight;
  generate.on_event = [&](SensorEvent event) {
    if (auto* frame = std::get_if<RgbdFrame>(&event)) {
      auto shared = std::make_shared<const RgbdFrame>(*frame);
      for (const auto& store : stores_) {
        in_flight.push_back(pool.submit([store = store.get(), shared] { store->add(*shared); }));
      }
      while (in_flight.size() > window * stores_.size()) {
        in_flight.front().get();
        in_flight.pop_front();
      }
      frame->rgb.release();
      frame->depth_m.release();
    }
    events_.push_back(std::move(event));
  };
  try {
    summary_ = sim::generate::generate_dataset(site, dataset_dir, generate);
  } catch (...) {
    for (auto& f : in_flight) f.wait();
    throw;
  }
  for (auto& f : in_flight) f.get();  // an extraction's failure surfaces here
}

RecordedDataset::~RecordedDataset() = default;

std::unique_ptr<SensorStream> RecordedDataset::stream() const {
  return std::make_unique<Replay>(*this);
}

const slam::feature::FeatureStore* RecordedDataset::features(
    const slam::feature::FeatureOptions& options) const {
  for (const auto& store : stores_)
    if (store->options() == options) return store.get();
  return nullptr;
}

void run_recorded(const RecordedDataset& dataset, std::vector<StreamedRun>& runs, int jobs,
                  const std::function<void(std::size_t)>& on_run_done) {
  for (const StreamedRun& run : runs) {
    if (dataset.features(run.slam.features) == nullptr) {
      throw std::invalid_argument(
          fmt::format("run {}: its feature options were not extracted", run.run_dir.string()));
    }
  }
  std::mutex mutex;
  std::exception_ptr first_error;
  parallel_for(clamp_thread_count(jobs), runs.size(), [&](std::size_t i) {
    {
      std::lock_guard lock(mutex);
      if (first_error) return;  // stop starting runs after a failure
    }
    try {
      StreamedRun& run = runs[i];
      const auto stream = dataset.stream();
      const auto system = slam::system::run_slam(*stream, run.slam, run.summary, {},
                                                 dataset.features(run.slam.features));
      slam::io::write_run_folder(run.run_dir, *system, run.summary, /*overwrite=*/false,
                                 run.run_info);
      if (on_run_done) on_run_done(i);
    } catch (...) {
      std::lock_guard lock(mutex);
      if (!first_error) first_error = std::current_exception();
    }
  });
  if (first_error) std::rethrow_exception(first_error);
}

}  // namespace wifislam::study
