#include "peers/external_run.hpp"

#include <unistd.h>

#include <fmt/format.h>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/run_format.hpp"
#include "peers/external_outputs.hpp"

namespace wifislam::peers {

namespace fs = std::filesystem;

namespace {

/// The running wifislam binary, for {wifislam}.
fs::path this_binary() {
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::path("wifislam") : self;
}

nlohmann::json run_json(const ExternalRunRequest& request, const std::vector<std::string>& argv,
                        const ExternalRunResult& result, const ImportedOutputs& imported,
                        const fs::path& staging) {
  nlohmann::json j = {
      {run_folder::run_key::kFormat, run_folder::kFormatName},
      {run_folder::run_key::kFormatVersion, run_folder::kFormatVersion},
      {run_folder::run_key::kFrontend, std::string(kExternalPrefix) + request.system.name},
      {run_folder::run_key::kWifi, request.wifi},
      {"seed", request.seed},
      {"frames", imported.frames},
      {"keyframes", imported.keyframes},
      {"loop_closures", imported.loop_closures},
      {"external",
       {{"system_file", request.system.file.string()},
        {"command", argv},
        {"status", result.status},
        {"exit_code", result.process.exit_code},
        {"timeout_s", request.system.timeout_s},
        {"wall_s", result.process.wall_s},
        {"cpu_s", result.process.cpu_s},
        {"stdout_tail", file_tail(staging / "stdout.log")},
        {"stderr_tail", file_tail(staging / "stderr.log")}}}};
  j.update(request.extra_run_info);
  return j;
}

}  // namespace

ExternalRunRequest external_run_request(const std::string& frontend, bool wifi,
                                        const fs::path& dataset, const fs::path& run_dir) {
  ExternalRunRequest request;
  request.system = resolve_external_system(frontend);
  if (wifi && !request.system.wifi) {
    throw InvalidInputError(fmt::format(
        "{}: the system reads no Wi-Fi (wifi: false in {}); run it without the Wi-Fi variant",
        frontend, request.system.file.string()));
  }
  request.wifi = wifi;
  request.dataset = dataset;
  request.run_dir = run_dir;
  return request;
}

ExternalRunResult run_external_system(const ExternalRunRequest& request) {
  if (!fs::is_directory(request.dataset)) {
    throw IoError(request.dataset.string() + ": dataset folder not found");
  }
  AtomicDirectory folder(request.run_dir, request.overwrite);
  const fs::path staging = fs::absolute(folder.staging_path());
  ExternalRunValues values;
  values.dataset = fs::absolute(request.dataset).lexically_normal();
  values.out = staging / "system";
  values.seed = request.seed;
  values.wifi = request.wifi;
  values.wifislam_binary = this_binary();
  fs::create_directories(values.out);
  if (request.system.export_for) {
    // The export links point at the dataset's files; the run folder keeps them beside the run.
    values.rgbd_export = staging / "rgbd_export";
    PeerExportOptions options;
    options.peer = *request.system.export_for;
    export_for_peer(values.dataset, values.rgbd_export, options);
  }
  const std::vector<std::string> argv = expand_command(request.system, values);

  ExternalRunResult result;
  ProcessRequest process;
  process.argv = argv;
  process.working_dir = values.out;
  process.stdout_file = staging / "stdout.log";
  process.stderr_file = staging / "stderr.log";
  process.timeout_s = request.system.timeout_s;
  result.process = run_process(process);
  result.status = result.process.describe(request.system.timeout_s);
  ImportedOutputs imported;
  if (result.process.succeeded()) {
    try {
      imported = import_external_outputs(request.system, values.out, staging, request.wifi,
                                         result.process.cpu_s, result.process.wall_s);
      result.ok = true;
      result.status = "ok";
    } catch (const Error& e) {
      result.status = std::string("unusable output: ") + e.what();
      for (const char* f :
           {run_folder::kTrajectory, run_folder::kKeyframes, run_folder::kLoopClosures,
            run_folder::kGraph, run_folder::kTiming, run_folder::kWifiClusters}) {
        fs::remove(staging / f);  // nothing half-imported looks like a finished run
      }
    }
  }
  write_file_atomic(staging / run_folder::kRun,
                    run_json(request, argv, result, imported, staging).dump(1) + "\n");
  folder.commit();
  return result;
}

}  // namespace wifislam::peers
