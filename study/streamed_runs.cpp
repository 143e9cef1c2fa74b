#include "study/streamed_runs.hpp"

#include <algorithm>
#include <exception>
#include <stdexcept>
#include <system_error>
#include <thread>

#include <fmt/format.h>

#include "core/sensor_stream_fanout.hpp"
#include "core/thread_start.hpp"
#include "sim/generate/dataset_writer.hpp"
#include "sim/generate/generator_stream.hpp"
#include "slam/io/run_folder_writer.hpp"
#include "slam/system/run_slam.hpp"

namespace wifislam::study {

namespace {

/// A group of runs reading one fan-out, each on a thread of its own.
class RunGroup {
 public:
  RunGroup(std::vector<StreamedRun>& runs, std::vector<std::size_t> members,
           const SensorStreamFacts& facts, const std::function<void(std::size_t)>& on_run_done)
      : runs_(runs),
        members_(std::move(members)),
        fanout_(facts, static_cast<int>(members_.size())),
        errors_(members_.size()),
        on_run_done_(on_run_done) {}

  /// Starts one thread per member; returns the members no thread could be started for (the
  /// fan-out no longer waits for them). Throws when not even one could be started.
  std::vector<std::size_t> start() {
    for (std::size_t slot = 0; slot < members_.size(); ++slot) {
      if (start_threads(threads_, 1, [this, slot] { consume(slot); }) == 1) continue;
      std::vector<std::size_t> unstarted;
      for (std::size_t rest = slot; rest < members_.size(); ++rest) {
        fanout_.leave(static_cast<int>(rest));
        unstarted.push_back(members_[rest]);
      }
      members_.resize(slot);
      if (members_.empty()) {
        throw std::system_error(std::make_error_code(std::errc::resource_unavailable_try_again),
                                "cannot start a thread for a SLAM run");
      }
      return unstarted;
    }
    return {};
  }

  SensorStreamFanout& fanout() { return fanout_; }

  /// Joins the threads; rethrows the first run's failure.
  void finish() {
    for (std::thread& t : threads_) t.join();
    threads_.clear();
    for (std::size_t slot = 0; slot < members_.size(); ++slot)
      if (errors_[slot]) std::rethrow_exception(errors_[slot]);
  }

  ~RunGroup() {
    fanout_.abort("stopped");  // no-op for finished consumers; wakes any still waiting
    for (std::thread& t : threads_) t.join();
  }

 private:
  void consume(std::size_t slot) {
    StreamedRun& run = runs_[members_[slot]];
    try {
      const auto system =
          slam::system::run_slam(fanout_.consumer(static_cast<int>(slot)), run.slam, run.summary);
      slam::io::write_run_folder(run.run_dir, *system, run.summary, /*overwrite=*/false,
                                 run.run_info);
      if (on_run_done_) on_run_done_(members_[slot]);
    } catch (...) {
      errors_[slot] = std::current_exception();
      fanout_.leave(static_cast<int>(slot));
    }
  }

  std::vector<StreamedRun>& runs_;
  std::vector<std::size_t> members_;
  SensorStreamFanout fanout_;
  std::vector<std::exception_ptr> errors_;
  const std::function<void(std::size_t)>& on_run_done_;
  std::vector<std::thread> threads_;
};

std::vector<std::size_t> take_group(std::vector<std::size_t>& waiting, int jobs) {
  const auto n = std::min(waiting.size(), static_cast<std::size_t>(std::max(1, jobs)));
  std::vector<std::size_t> group(waiting.begin(), waiting.begin() + static_cast<long>(n));
  waiting.erase(waiting.begin(), waiting.begin() + static_cast<long>(n));
  return group;
}

}  // namespace

sim::generate::GenerateSummary generate_with_runs(
    std::shared_ptr<const sim::site::Site> site, const std::filesystem::path& dataset_dir,
    sim::generate::GenerateOptions generate, std::vector<StreamedRun>& runs, int jobs,
    const std::function<void(std::size_t)>& on_run_done) {
  if (generate.on_event) throw std::invalid_argument("generate_with_runs sets on_event itself");
  std::vector<std::size_t> waiting(runs.size());
  for (std::size_t i = 0; i < runs.size(); ++i) waiting[i] = i;

  sim::generate::GenerateSummary summary;
  {
    const SensorStreamFacts facts = sim::generate::generated_stream_facts(
        *site, fmt::format("dataset {} (frames streamed as it was generated)",
                           dataset_dir.filename().string()));
    RunGroup group(runs, take_group(waiting, jobs), facts, on_run_done);
    const std::vector<std::size_t> unstarted = group.start();
    waiting.insert(waiting.begin(), unstarted.begin(), unstarted.end());
    generate.on_event = [&group](SensorEvent event) { group.fanout().push(std::move(event)); };
    try {
      summary = sim::generate::generate_dataset(site, dataset_dir, generate);
    } catch (const std::exception& e) {
      group.fanout().abort(e.what());
      throw;  // the group's destructor joins its threads
    }
    group.fanout().close();
    group.finish();
  }
  // More runs than jobs: render again in memory for each further group.
  sim::generate::GenerateOptions rerender;
  rerender.max_frames = generate.max_frames;
  rerender.render = generate.render;
  while (!waiting.empty()) {
    sim::generate::GeneratorStream stream(site, rerender);
    RunGroup group(runs, take_group(waiting, jobs), SensorStreamFacts::of(stream), on_run_done);
    const std::vector<std::size_t> unstarted = group.start();
    waiting.insert(waiting.begin(), unstarted.begin(), unstarted.end());
    group.fanout().pump(stream);
    group.finish();
  }
  return summary;
}

}  // namespace wifislam::study
