#include "interop/external_run.hpp"

#include <unistd.h>

#include <fmt/format.h>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/run_format.hpp"
#include "interop/external_outputs.hpp"

namespace wifislam::interop {

namespace fs = std::filesystem;

namespace {

/// The system's folder in the run folder ({out} while it ran).
constexpr const char* kSystemFolder = "system";

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
  const fs::path staging = fs::absolute(folder.staging_path()).lexically_normal();
  const fs::path final_dir = request.within.of(fs::absolute(request.run_dir).lexically_normal());
  ExternalRunValues values;
  values.dataset = fs::absolute(request.dataset).lexically_normal();
  // The system works two levels below the run folder, in a scratch folder of its own: what it
  // does around {out} ($2/../trajectory.txt, mkdir $2/../run.json, rm -rf "$(dirname "$2")")
  // reaches that scratch folder, never a file wifislam writes. Its folder becomes system/ after.
  const fs::path scratch = staging / ".system";
  values.out = scratch / "out";
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
  // Everything the system started has ended when this returns (process_runner.hpp).
  result.process = run_process(process);
  result.status = result.process.describe(request.system.timeout_s);
  // The system runs as the user: it could replace the run's folder under construction ($2/../..)
  // or its scratch folder ($2/..) by a link to elsewhere. Nothing is then moved, read or deleted
  // through the link (remove_all of a link removes the link only).
  const auto real_directory = [](const fs::path& p) {
    std::error_code ec;
    return fs::symlink_status(p, ec).type() == fs::file_type::directory;
  };
  if (!real_directory(staging)) {
    throw IoError(staging.string() +
                  ": the external system replaced the run folder under construction; nothing in "
                  "it is used or removed");
  }
  ImportedOutputs imported;
  const fs::path system_dir = staging / kSystemFolder;
  try {
    // Its folder, as it left it (links kept as links, never followed), becomes system/; a folder
    // it removed or replaced by something else is the run's failure, not ours.
    std::error_code ec;
    if (!real_directory(scratch)) {
      fs::remove(scratch, ec);  // the link, not what it names
      fs::create_directories(system_dir);
      throw ParseError(values.out.string(), "", "the system removed or replaced its folder");
    }
    if (fs::is_directory(fs::symlink_status(values.out, ec))) {
      fs::rename(values.out, system_dir);
    } else {
      fs::create_directories(system_dir);
      if (result.process.succeeded()) {
        throw ParseError(values.out.string(), "", "the system removed or replaced its folder");
      }
    }
    fs::remove_all(scratch, ec);
    if (result.process.succeeded()) {
      imported = import_external_outputs(request.system, system_dir, staging, request.wifi,
                                         result.process.cpu_s, result.process.wall_s);
      result.ok = true;
      result.status = "ok";
    }
  } catch (const std::exception& e) {  // Error, or a filesystem_error in what it left
    result.ok = false;
    result.status = std::string("unusable output: ") + e.what();
    imported = {};
    std::error_code ec;
    for (const char* f :
         {run_folder::kTrajectory, run_folder::kKeyframes, run_folder::kLoopClosures,
          run_folder::kGraph, run_folder::kTiming, run_folder::kWifiClusters}) {
      fs::remove_all(staging / f, ec);  // nothing half-imported looks like a finished run
    }
  }
  // Messages and run.json name paths that exist once the run folder (and the folder holding
  // it) is in place: the system's working folder becomes system/, the staging folder the run
  // folder.
  const FinalPaths system_final(values.out, final_dir / kSystemFolder),
      run_final(staging, final_dir);
  const auto final_text = [&](const std::string& text) {
    return request.within.in_text(run_final.in_text(system_final.in_text(text)));
  };
  result.status = final_text(result.status);
  std::vector<std::string> shown_argv;
  for (const std::string& a : argv) shown_argv.push_back(final_text(a));
  std::error_code ec;
  fs::remove_all(staging / run_folder::kRun, ec);  // ours to write, whatever the system left there
  // So is the evaluation compare and study run write into the run folder later: a link the system
  // left at eval/ made that evaluation replace the folder it named (remove_all takes the link).
  for (const char* name : {"eval", "eval.partial", "eval.replaced"})
    fs::remove_all(staging / name, ec);
  write_file_atomic(staging / run_folder::kRun,
                    run_json(request, shown_argv, result, imported, staging).dump(1) + "\n");
  folder.commit();
  return result;
}

}  // namespace wifislam::interop
